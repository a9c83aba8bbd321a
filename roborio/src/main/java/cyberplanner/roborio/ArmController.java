package cyberplanner.roborio;

import cyberplanner.roborio.can.Setpoint;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.BooleanSupplier;
import java.util.function.LongSupplier;
import java.util.function.Supplier;

/**
 * The robot loop's part, free of WPILib (the wpilib2026 and wpilib2027 subsystems call it from
 * periodic()): publish the measured state, read the setpoints, apply them while the guard says
 * USE, otherwise run the fallback. The robot controller stays the only source of motor commands:
 * the daemon proposes, this commands. Nothing is applied while the robot is disabled or while a
 * team command has taken the joints (manual override). Main loop only.
 */
public final class ArmController {
  /**
   * The parts: where the setpoints come from and go (joints: one per joint of the daemon's config,
   * in its [[joints]] order, each with the name the config gives it, its motor and its gravity
   * model), the measured state (as many joints), the clocks.
   */
  public record Parts(CyberPlannerClient client, SetpointSource source, List<ArmJoint> joints,
      Supplier<ArmState> measured, BooleanSupplier enabled, LongSupplier clockMicros) {
    public Parts {
      if (client == null || source == null || measured == null || enabled == null || clockMicros == null) {
        throw new IllegalArgumentException("a part is null");
      }
      if (joints == null) throw new IllegalArgumentException("joints is null");
      joints = List.copyOf(joints);
      chainOf(joints);  // 1 to MAX_JOINTS, distinct names
    }

    /** The joints' names by index. */
    public JointChain chain() {
      return chainOf(joints);
    }

    private static JointChain chainOf(List<ArmJoint> joints) {
      List<String> names = new ArrayList<>(joints.size());
      for (ArmJoint joint : joints) names.add(joint.name());
      return JointChain.of(names);
    }
  }

  private final Parts parts;
  private final JointChain joints;
  private final String[] jointNames;
  private final SetpointGuard guard;
  private final Fallback fallback;
  private SetpointGuard.Verdict verdict = SetpointGuard.Verdict.DAEMON_LOST;
  private boolean manualOverride;
  private MoveHandle move;
  private MoveHandle holdUnlessReplaced;
  private MoveState seenMoveState;
  private long moveStateChanges;

  /**
   * The guard must guard the parts' joints, and the source must read setpoints for them
   * (SetpointSource.checkJoints): IllegalArgumentException, naming both, otherwise.
   */
  public ArmController(Parts parts, SetpointGuard guard, Fallback fallback) {
    if (parts == null || guard == null || fallback == null) throw new IllegalArgumentException("a part is null");
    this.parts = parts;
    this.joints = parts.chain();
    this.jointNames = joints.names().toArray(new String[0]);
    if (!guard.joints().equals(joints)) {
      throw new IllegalArgumentException(
          "the guard's joints (" + guard.joints() + ") are not the arm's (" + joints + ")");
    }
    parts.source().checkJoints(joints);
    this.guard = guard;
    this.fallback = fallback;
  }

  /** The defaults: 50 ms setpoint age, 250 ms status age, each joint held where it is against its gravity. */
  public ArmController(Parts parts) {
    this(parts, new SetpointGuard(parts.chain()), new HoldFallback(parts.joints()));
  }

  /** One robot loop. */
  public void periodic() {
    sendPendingHold();
    ArmState state = parts.measured().get();
    if (state == null || state.count() != joints.count()) {
      // The supplier's shape is the robot program's wiring, not a reading: it is wrong every loop.
      throw new IllegalArgumentException("the measured state " + (state == null ? "is null" : "has " + state.count()
          + " joints") + ", the arm " + joints.count() + ": " + joints);
    }
    parts.client().publishState(state);
    long now = parts.clockMicros().getAsLong();
    parts.source().poll(guard, now);
    guard.onDaemonJoints(parts.client().daemonJointNames());
    verdict = guard.verdict(now);
    if (!parts.enabled().getAsBoolean() || manualOverride) {
      fallback.reset();
    } else if (verdict == SetpointGuard.Verdict.USE) {
      fallback.reset();
      for (int i = 0; i < joints.count(); ++i) apply(parts.joints().get(i).output(), guard.latest(i));
    } else {
      fallback.run(verdict, state);
    }
    if (move != null && move.state() != seenMoveState) {
      seenMoveState = move.state();
      moveStateChanges++;
    }
  }

  private static void apply(JointOutput output, Setpoint setpoint) {
    output.apply(setpoint.position(), setpoint.velocity(), setpoint.feedforwardVolts());
  }

  /**
   * Sends a goal (ending a manual override: the daemon streams again for it). It replaces the
   * running move, which the daemon answers CANCELLED, and is planned from that move's motion; a
   * hold left by cancelUnlessReplaced is then not sent. A pose that is not named and has not one
   * position per joint throws IllegalArgumentException, saying both counts, and sends nothing.
   */
  public MoveHandle moveTo(Pose pose) {
    joints.check(pose);
    manualOverride = false;
    move = parts.client().moveTo(pose);
    if (move.isFinished()) sendPendingHold();  // not sent (no link): it replaces nothing
    holdUnlessReplaced = null;
    return move;
  }

  /** Stops a move that is not finished: the daemon brakes to rest and holds (CANCELLED). */
  public void cancel(MoveHandle handle) {
    if (handle == holdUnlessReplaced) holdUnlessReplaced = null;
    if (handle != null && !handle.isFinished()) parts.client().cancel(handle, CancelAction.HOLD);
  }

  /**
   * Stops a move at the next periodic() unless a goal is sent first (docs/roborio.md, "Chained
   * moves"). An interrupted command cannot know whether a command that sends a goal takes over:
   * the command scheduler ends it before it initializes its successor, in the same loop. A
   * successor's goal is planned from the running motion, which is never slower than braking
   * first; a cancel sent at once would brake the mechanism before that goal arrives.
   */
  public void cancelUnlessReplaced(MoveHandle handle) {
    if (handle != null && !handle.isFinished()) holdUnlessReplaced = handle;
  }

  private void sendPendingHold() {
    MoveHandle handle = holdUnlessReplaced;
    holdUnlessReplaced = null;
    if (handle != null) cancel(handle);
  }

  /**
   * A team command takes the joints: the daemon is asked to stop streaming (RELEASE) and this
   * controller applies neither setpoints nor the fallback until endManualOverride() or moveTo().
   */
  public void beginManualOverride() {
    manualOverride = true;
    holdUnlessReplaced = null;  // the release ends every open goal
    parts.client().release();
  }

  /** The team command is done: the fallback holds where the joints are until the next goal. */
  public void endManualOverride() {
    manualOverride = false;
  }

  public boolean isManualOverride() {
    return manualOverride;
  }

  /** The verdict of the latest periodic(): USE, or why the setpoints were not used. */
  public SetpointGuard.Verdict verdict() {
    return verdict;
  }

  public SetpointGuard guard() {
    return guard;
  }

  /** The arm's joints, by index and by name (the names the robot program gave its ArmJoints). */
  public JointChain joints() {
    return joints;
  }

  public CyberPlannerClient client() {
    return parts.client();
  }

  /** The latest move sent through this controller, or null. */
  public MoveHandle move() {
    return move;
  }

  /** Fills inputs with this loop's values (call after periodic()). */
  public void updateInputs(ArmInputs inputs) {
    CyberPlannerClient client = parts.client();
    inputs.linkConnected = client.link().isConnected();
    inputs.linkError = client.link().lastError();
    inputs.daemonStatusAgeS = client.daemonStatusAgeS();
    inputs.daemonAlive = client.isDaemonAlive(0.5);
    inputs.daemonMode = client.daemonMode() == null ? "" : client.daemonMode().name();
    inputs.verdict = verdict.name();
    inputs.manualOverride = manualOverride;
    inputs.moveRequestId = move == null ? 0 : move.requestId();
    inputs.moveState = move == null ? "" : move.state().name();
    inputs.moveReason = move == null ? "" : move.reason();
    inputs.moveDurationS = move == null ? 0 : move.durationS();
    inputs.moveStateChanges = moveStateChanges;
    inputs.daemonJoints = client.daemonJoints();
    int count = joints.count();
    if (!Arrays.equals(inputs.jointNames, jointNames)) {
      inputs.jointNames = jointNames.clone();
      inputs.lostFrames = new long[count];
      inputs.repeatedFrames = new long[count];
    }
    for (int i = 0; i < count; ++i) {
      inputs.lostFrames[i] = guard.lostFrames(i);
      inputs.repeatedFrames[i] = guard.repeatedFrames(i);
    }
    inputs.undecodableMessages = client.undecodableMessages();
  }
}

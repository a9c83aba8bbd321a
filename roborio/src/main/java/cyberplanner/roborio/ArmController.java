package cyberplanner.roborio;

import cyberplanner.roborio.can.Setpoint;
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
   * The parts: where the setpoints come from and go (joint0 and joint1: the motors of the config's
   * first and second [[joints]]), the measured state, the clocks.
   */
  public record Parts(CyberPlannerClient client, SetpointSource source, JointOutput joint0, JointOutput joint1,
      Supplier<ArmState> measured, BooleanSupplier enabled, LongSupplier clockMicros) {
    /** The motor of a joint. */
    public JointOutput output(Joint joint) {
      return joint == Joint.JOINT_0 ? joint0 : joint1;
    }
  }

  private final Parts parts;
  private final SetpointGuard guard;
  private final Fallback fallback;
  private SetpointGuard.Verdict verdict = SetpointGuard.Verdict.DAEMON_LOST;
  private boolean manualOverride;
  private MoveHandle move;
  private MoveHandle holdUnlessReplaced;
  private MoveState seenMoveState;
  private long moveStateChanges;

  public ArmController(Parts parts, SetpointGuard guard, Fallback fallback) {
    this.parts = parts;
    this.guard = guard;
    this.fallback = fallback;
  }

  /** The defaults: 50 ms setpoint age, 250 ms status age, hold where it is against gravity. */
  public ArmController(Parts parts, JointGravity joint0Gravity, JointGravity joint1Gravity) {
    this(parts, new SetpointGuard(0.05, 0.25),
        new HoldFallback(parts.joint0(), parts.joint1(), joint0Gravity, joint1Gravity));
  }

  /** One robot loop. */
  public void periodic() {
    sendPendingHold();
    ArmState state = parts.measured().get();
    parts.client().publishState(state);
    long now = parts.clockMicros().getAsLong();
    parts.source().poll(guard, now);
    verdict = guard.verdict(now);
    if (!parts.enabled().getAsBoolean() || manualOverride) {
      fallback.reset();
    } else if (verdict == SetpointGuard.Verdict.USE) {
      fallback.reset();
      for (Joint joint : Joint.values()) apply(parts.output(joint), guard.latest(joint));
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
   * hold left by cancelUnlessReplaced is then not sent.
   */
  public MoveHandle moveTo(Pose pose) {
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
    inputs.joint0LostFrames = guard.lostFrames(Joint.JOINT_0);
    inputs.joint1LostFrames = guard.lostFrames(Joint.JOINT_1);
    inputs.joint0RepeatedFrames = guard.repeatedFrames(Joint.JOINT_0);
    inputs.joint1RepeatedFrames = guard.repeatedFrames(Joint.JOINT_1);
    inputs.undecodableMessages = client.undecodableMessages();
  }
}

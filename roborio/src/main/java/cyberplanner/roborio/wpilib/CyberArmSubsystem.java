package cyberplanner.roborio.wpilib;

import cyberplanner.roborio.ArmState;
import cyberplanner.roborio.CyberPlannerClient;
import cyberplanner.roborio.Joint;
import cyberplanner.roborio.MoveHandle;
import cyberplanner.roborio.Pose;
import cyberplanner.roborio.SetpointGuard;
import cyberplanner.roborio.SetpointSource;
import cyberplanner.roborio.can.Setpoint;
import edu.wpi.first.wpilibj2.command.SubsystemBase;
import java.util.function.LongSupplier;
import java.util.function.Supplier;

/**
 * The elevator and arm driven by cyber-plannerd (docs/roborio.md). Every periodic(): publishes the
 * measured state, reads the setpoints, and applies them while the guard says USE; otherwise the
 * fallback runs (by default: hold where the mechanism was when the setpoints stopped). The
 * roboRIO stays the only source of motor commands: the daemon proposes, this subsystem commands.
 */
public class CyberArmSubsystem extends SubsystemBase {
  /** What the robot does while cyber-planner setpoints must not be used. */
  public interface Fallback {
    /** Called every loop while the verdict is not USE; resumed() when it is again. */
    void run(SetpointGuard.Verdict why, ArmState measured);

    default void resumed() {}
  }

  private final CyberPlannerClient client;
  private final SetpointSource source;
  private final JointOutput elevator;
  private final JointOutput arm;
  private final Supplier<ArmState> measured;
  private final SetpointGuard guard;
  private final Fallback fallback;
  private final LongSupplier clockMicros;
  private SetpointGuard.Verdict verdict = SetpointGuard.Verdict.DAEMON_LOST;

  /**
   * @param clockMicros the robot's clock in microseconds (e.g. RobotController::getFPGATime)
   */
  public CyberArmSubsystem(CyberPlannerClient client, SetpointSource source, JointOutput elevator, JointOutput arm,
      Supplier<ArmState> measured, SetpointGuard guard, Fallback fallback, LongSupplier clockMicros) {
    this.client = client;
    this.source = source;
    this.elevator = elevator;
    this.arm = arm;
    this.measured = measured;
    this.guard = guard;
    this.fallback = fallback;
    this.clockMicros = clockMicros;
  }

  /** The defaults: 50 ms setpoint age, 250 ms status age, hold on loss, System.nanoTime. */
  public CyberArmSubsystem(CyberPlannerClient client, SetpointSource source, JointOutput elevator, JointOutput arm,
      Supplier<ArmState> measured) {
    this(client, source, elevator, arm, measured, new SetpointGuard(0.05, 0.25), new HoldFallback(elevator, arm),
        () -> System.nanoTime() / 1000);
  }

  @Override
  public void periodic() {
    ArmState state = measured.get();
    client.publishState(state.elevatorM(), state.elevatorMps(), state.armRad(), state.armRadps(), state.heldCoral(),
        state.heldAlgae());
    long now = clockMicros.getAsLong();
    source.poll(guard, now);
    SetpointGuard.Verdict next = guard.verdict(now);
    if (next == SetpointGuard.Verdict.USE) {
      if (verdict != SetpointGuard.Verdict.USE) fallback.resumed();
      apply(elevator, guard.latest(Joint.ELEVATOR));
      apply(arm, guard.latest(Joint.ARM));
    } else {
      fallback.run(next, state);
    }
    verdict = next;
  }

  private static void apply(JointOutput output, Setpoint setpoint) {
    output.apply(setpoint.position(), setpoint.velocity(), setpoint.feedforwardVolts());
  }

  /** Sends a goal; the handle reports its progress. */
  public MoveHandle moveTo(Pose pose) {
    return client.moveTo(pose);
  }

  /** A command that moves to pose and finishes when the move is finished (see MoveToPoseCommand). */
  public MoveToPoseCommand moveToCommand(Pose pose) {
    return new MoveToPoseCommand(this, pose);
  }

  /** The verdict of the latest periodic(): USE, or why the fallback runs. */
  public SetpointGuard.Verdict verdict() {
    return verdict;
  }

  public SetpointGuard guard() {
    return guard;
  }

  public CyberPlannerClient client() {
    return client;
  }
}

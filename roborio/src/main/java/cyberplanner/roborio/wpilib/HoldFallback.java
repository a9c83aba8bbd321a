package cyberplanner.roborio.wpilib;

import cyberplanner.roborio.ArmState;
import cyberplanner.roborio.SetpointGuard;

/**
 * The default fallback: when the setpoints stop, hold both joints where they were measured at that
 * moment (zero velocity, no feedforward beyond the controller's own gains). A motor controller keeps
 * its last request, so doing nothing would keep following the last, stale setpoint.
 */
public final class HoldFallback implements CyberArmSubsystem.Fallback {
  private final JointOutput elevator;
  private final JointOutput arm;
  private ArmState held;

  public HoldFallback(JointOutput elevator, JointOutput arm) {
    this.elevator = elevator;
    this.arm = arm;
  }

  @Override
  public void run(SetpointGuard.Verdict why, ArmState measured) {
    if (held == null) held = measured;
    elevator.apply(held.elevatorM(), 0.0, 0.0);
    arm.apply(held.armRad(), 0.0, 0.0);
  }

  @Override
  public void resumed() {
    held = null;
  }
}

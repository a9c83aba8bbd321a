package cyberplanner.roborio;

/**
 * The default fallback: hold both joints where they are measured at the moment the setpoints stop
 * being usable, against gravity. The hold is captured afresh on every change to unusable
 * (ArmController calls reset() whenever it does not run the fallback: setpoints used, robot
 * disabled, manual override), so a robot enabled after sagging holds where it stands, not where it
 * booted. Position control at zero velocity, with the gravity feedforward of the team's model:
 * docs/roborio.md has the controllers' kG at 0 because the setpoints carry it. A motor controller
 * keeps its last request, so doing nothing would follow the last, stale setpoint.
 */
public final class HoldFallback implements Fallback {
  private final JointOutput elevator;
  private final JointOutput arm;
  private final JointGravity elevatorGravity;
  private final JointGravity armGravity;
  private ArmState held;

  public HoldFallback(JointOutput elevator, JointOutput arm, JointGravity elevatorGravity, JointGravity armGravity) {
    this.elevator = elevator;
    this.arm = arm;
    this.elevatorGravity = elevatorGravity;
    this.armGravity = armGravity;
  }

  @Override
  public void run(SetpointGuard.Verdict why, ArmState measured) {
    if (held == null) held = measured;
    elevator.apply(held.elevatorM(), 0.0, elevatorGravity.volts(held.elevatorM()));
    arm.apply(held.armRad(), 0.0, armGravity.volts(held.armRad()));
  }

  @Override
  public void reset() {
    held = null;
  }

  /** The pose being held, or null while none is. */
  public ArmState held() {
    return held;
  }
}

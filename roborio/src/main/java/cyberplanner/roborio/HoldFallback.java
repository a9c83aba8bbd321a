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
  private final JointOutput[] outputs;
  private final JointGravity[] gravity;
  private ArmState held;

  /** Joint 0's and joint 1's motor and gravity model, as in ArmController.Parts. */
  public HoldFallback(JointOutput joint0, JointOutput joint1, JointGravity joint0Gravity, JointGravity joint1Gravity) {
    this.outputs = new JointOutput[] {joint0, joint1};
    this.gravity = new JointGravity[] {joint0Gravity, joint1Gravity};
  }

  @Override
  public void run(SetpointGuard.Verdict why, ArmState measured) {
    if (held == null) held = measured;
    for (Joint joint : Joint.values()) {
      double position = held.position(joint);
      outputs[joint.index()].apply(position, 0.0, gravity[joint.index()].volts(position));
    }
  }

  @Override
  public void reset() {
    held = null;
  }

  /** The state being held, or null while none is. */
  public ArmState held() {
    return held;
  }
}

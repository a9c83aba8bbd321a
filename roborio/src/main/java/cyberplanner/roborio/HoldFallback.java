package cyberplanner.roborio;

import java.util.List;

/**
 * The default fallback: hold every joint where it is measured at the moment the setpoints stop
 * being usable, against gravity. The hold is captured afresh on every change to unusable
 * (ArmController calls reset() whenever it does not run the fallback: setpoints used, robot
 * disabled, manual override), so a robot enabled after sagging holds where it stands, not where it
 * booted. Position control at zero velocity, with the gravity feedforward of the team's model:
 * docs/roborio.md has the controllers' kG at 0 because the setpoints carry it. A motor controller
 * keeps its last request, so doing nothing would follow the last, stale setpoint.
 */
public final class HoldFallback implements Fallback {
  private final List<ArmJoint> joints;
  private ArmState held;

  /** Each joint's motor and gravity model, in chain order, as ArmController.Parts has them. */
  public HoldFallback(List<ArmJoint> joints) {
    if (joints == null || joints.isEmpty()) throw new IllegalArgumentException("a hold needs the arm's joints");
    this.joints = List.copyOf(joints);
  }

  @Override
  public void run(SetpointGuard.Verdict why, ArmState measured) {
    if (held == null) {
      if (measured.count() != joints.size()) {
        throw new IllegalArgumentException("the measured state has " + measured.count() + " joints, the hold "
            + joints.size());
      }
      held = measured;
    }
    for (int i = 0; i < joints.size(); ++i) {
      double position = held.position(i);
      ArmJoint joint = joints.get(i);
      joint.output().apply(position, 0.0, joint.gravity().volts(position));
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

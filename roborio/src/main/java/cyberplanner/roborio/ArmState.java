package cyberplanner.roborio;

import java.util.Arrays;
import java.util.List;

/**
 * The measured state the robot publishes on ARM_STATE: each joint's position and velocity (m and
 * m/s for a prismatic joint, rad and rad/s for a revolute one; joints in the order of the config's
 * [[joints]]) and the game pieces held now, by their config names. Positions are not checked for
 * being finite: a bad encoder reading must not throw in the robot loop; the daemon ignores such a
 * state (counting it in decode_errors), stops when its state goes stale, and the guard falls back.
 * The pieces are checked as in Pose (IllegalArgumentException).
 */
public record ArmState(double joint0Position, double joint0Velocity, double joint1Position, double joint1Velocity,
    List<String> pieces) {
  public ArmState {
    pieces = Checks.pieces(pieces);
  }

  /** Both joints measured, nothing held. */
  public static ArmState of(double joint0Position, double joint0Velocity, double joint1Position,
      double joint1Velocity) {
    return new ArmState(joint0Position, joint0Velocity, joint1Position, joint1Velocity, List.of());
  }

  /** The same state holding these pieces (replacing any named before; none: nothing held). */
  public ArmState holding(String... pieces) {
    if (pieces == null) throw new IllegalArgumentException("pieces is null");
    return holding(Arrays.asList(pieces));
  }

  public ArmState holding(List<String> pieces) {
    return new ArmState(joint0Position, joint0Velocity, joint1Position, joint1Velocity, pieces);
  }

  /** A joint's position, m or rad. */
  public double position(Joint joint) {
    return joint == Joint.JOINT_0 ? joint0Position : joint1Position;
  }

  /** A joint's velocity, m/s or rad/s. */
  public double velocity(Joint joint) {
    return joint == Joint.JOINT_0 ? joint0Velocity : joint1Velocity;
  }
}

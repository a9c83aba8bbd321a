package cyberplanner.roborio;

import java.util.Arrays;
import java.util.List;

/**
 * A goal for cyber-plannerd (ARM_GOAL, docs/lcm.md): the target of joint 0 and joint 1 (m for a
 * prismatic joint, rad for a revolute one, in the order of the config's [[joints]]), the game
 * pieces held during the move by their config names ([pieces.NAME]: they change the swept shape),
 * and the obstacle scene, by name and shifted horizontally away from the robot by sceneOffsetM.
 * Immutable: each with-method returns a new Pose, so one constant can serve several commands:
 *
 * <pre>{@code
 * Pose score = Pose.of(0.9, 2.1).holding("cube").inScene("grid").atSceneOffset(0.1);
 * }</pre>
 *
 * Invalid values (not finite, a null or non-ASCII name, more than MAX_PIECES pieces) throw
 * IllegalArgumentException where the Pose is built, not as a REJECTED answer later. Whether a
 * piece or scene exists and the offset is within the scene's range only the daemon knows.
 */
public record Pose(double joint0Position, double joint1Position, List<String> pieces, String sceneName,
    double sceneOffsetM) {
  /** The most pieces a goal can name (arm_goal_t.MAX_PIECES). */
  public static final int MAX_PIECES = Checks.MAX_PIECES;

  public Pose {
    Checks.finite("joint 0 position", joint0Position);
    Checks.finite("joint 1 position", joint1Position);
    pieces = Checks.pieces(pieces);
    Checks.ascii("scene name", sceneName);
    Checks.finite("scene offset", sceneOffsetM);
  }

  /** Joint 0 and joint 1 at these positions (m or rad), no piece, the default scene where it is. */
  public static Pose of(double joint0Position, double joint1Position) {
    return new Pose(joint0Position, joint1Position, List.of(), "", 0.0);
  }

  /** The same goal while holding these pieces (replacing any named before; none: nothing held). */
  public Pose holding(String... pieces) {
    if (pieces == null) throw new IllegalArgumentException("pieces is null");
    return holding(Arrays.asList(pieces));
  }

  /** The same goal while holding these pieces (replacing any named before). */
  public Pose holding(List<String> pieces) {
    return new Pose(joint0Position, joint1Position, pieces, sceneName, sceneOffsetM);
  }

  /** The same goal among the named scene's obstacles ("" = the config's default scene). */
  public Pose inScene(String sceneName) {
    return new Pose(joint0Position, joint1Position, pieces, sceneName, sceneOffsetM);
  }

  /**
   * The same goal with the scene shifted horizontally away from the robot by sceneOffsetM (e.g. the
   * robot stopped short of a field element), within the scene's offset_range_m; 0 = as configured.
   */
  public Pose atSceneOffset(double sceneOffsetM) {
    return new Pose(joint0Position, joint1Position, pieces, sceneName, sceneOffsetM);
  }

  /** The target of a joint, m or rad. */
  public double position(Joint joint) {
    return joint == Joint.JOINT_0 ? joint0Position : joint1Position;
  }
}

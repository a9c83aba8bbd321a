package cyberplanner.roborio;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * A goal for cyber-plannerd (ARM_GOAL, docs/lcm.md): the target of each joint (m for a prismatic
 * joint, rad for a revolute one, in the order of the config's [[joints]]) or the name of a pose of
 * the daemon's config ([poses.SET], resolved by the daemon for the held pieces; then positions is
 * empty), the game pieces held during the move by their config names ([pieces.NAME]: they change
 * the swept shape), and the obstacle scene, by name and shifted horizontally away from the robot
 * by sceneOffsetM. Immutable: each with-method returns a new Pose, so one constant can serve
 * several commands:
 *
 * <pre>{@code
 * Pose score = Pose.of(0.9, 2.1).holding("cube").inScene("grid").atSceneOffset(0.1);
 * Pose reach = Pose.of(0.4, 1.2, -0.6);  // a chain of three joints
 * Pose high = Pose.named("L3").holding("coral");
 * }</pre>
 *
 * Invalid values (not finite, a null or non-ASCII name, more than MAX_PIECES pieces or MAX_JOINTS
 * positions) throw IllegalArgumentException where the Pose is built, not as a REJECTED answer
 * later; a pose of another length than the arm's joint count throws where it is sent
 * (ArmController.moveTo, CyberArmSubsystem.moveToCommand; JointChain.check). Whether a piece,
 * scene or pose name exists and whether the offset is within the scene's range only the daemon
 * knows.
 */
public record Pose(List<Double> positions, String poseName, List<String> pieces, String sceneName,
    double sceneOffsetM) {
  /** The most pieces a goal can name (arm_goal_t.MAX_PIECES). */
  public static final int MAX_PIECES = Checks.MAX_PIECES;
  /** The most joints a goal can carry (arm_goal_t.MAX_JOINTS). */
  public static final int MAX_JOINTS = Checks.MAX_JOINTS;

  public Pose {
    positions = Checks.positions(positions);
    Checks.ascii("pose name", poseName);
    if (poseName.isEmpty() == positions.isEmpty()) {
      throw new IllegalArgumentException("a pose is either positions " + positions + " or a name \"" + poseName
          + "\", one of the two");
    }
    pieces = Checks.pieces(pieces);
    Checks.ascii("scene name", sceneName);
    Checks.finite("scene offset", sceneOffsetM);
  }

  /**
   * Each joint at these positions (m or rad), in the config's [[joints]] order: as many as the
   * robot has joints (ArmController.moveTo refuses another count, saying both).
   */
  public static Pose of(double... positions) {
    if (positions == null) throw new IllegalArgumentException("positions is null");
    List<Double> values = new ArrayList<>(positions.length);
    for (double value : positions) values.add(value);
    return new Pose(values, "", List.of(), "", 0.0);
  }

  /**
   * The pose the daemon's config names poseName for the held pieces ([poses.SET], docs/lcm.md,
   * "Named goals"): sent as the name, so the daemon resolves it with its own config; a name the
   * held set does not declare is REJECTED with the names it does.
   */
  public static Pose named(String poseName) {
    if ("".equals(poseName)) throw new IllegalArgumentException("a pose name is empty");
    return new Pose(List.of(), poseName, List.of(), "", 0.0);
  }

  /** True for a pose sent by name (positions is then empty). */
  public boolean isNamed() {
    return !poseName.isEmpty();
  }

  /** The same goal while holding these pieces (replacing any named before; none: nothing held). */
  public Pose holding(String... pieces) {
    if (pieces == null) throw new IllegalArgumentException("pieces is null");
    return holding(Arrays.asList(pieces));
  }

  /** The same goal while holding these pieces (replacing any named before). */
  public Pose holding(List<String> pieces) {
    return new Pose(positions, poseName, pieces, sceneName, sceneOffsetM);
  }

  /** The same goal among the named scene's obstacles ("" = the config's default scene). */
  public Pose inScene(String sceneName) {
    return new Pose(positions, poseName, pieces, sceneName, sceneOffsetM);
  }

  /**
   * The same goal with the scene shifted horizontally away from the robot by sceneOffsetM (e.g. the
   * robot stopped short of a field element), within the scene's offset_range_m; 0 = as configured.
   */
  public Pose atSceneOffset(double sceneOffsetM) {
    return new Pose(positions, poseName, pieces, sceneName, sceneOffsetM);
  }

  /** The target of joint index, m or rad (a named pose has none: IllegalStateException). */
  public double position(int index) {
    if (isNamed()) throw new IllegalStateException("pose \"" + poseName + "\" is resolved by the daemon");
    if (index < 0 || index >= positions.size()) {
      throw new IllegalArgumentException("the pose has " + positions.size() + " positions, no joint " + index);
    }
    return positions.get(index);
  }
}

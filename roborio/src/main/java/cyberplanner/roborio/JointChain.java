package cyberplanner.roborio;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

/**
 * The joints of the daemon's config, by index and by name: its [[joints]] names in chain order
 * (joint 0 nearer the robot's frame, each next one carried by the one before; docs/lcm.md, "Joints
 * by index"). A robot has 1 to MAX_JOINTS of them. Like a PhotonCamera's name in PhotonLib, the
 * robot program writes the names itself (ArmJoint), and ArmController checks them against the
 * joint_names of the daemon's ARM_DAEMON_STATUS (docs/roborio.md, "Joints by index and by name").
 * Immutable.
 */
public final class JointChain {
  /** The most joints a robot can have (arm_goal_t.MAX_JOINTS). */
  public static final int MAX_JOINTS = Checks.MAX_JOINTS;

  private final List<String> names;

  private JointChain(List<String> names) {
    this.names = names;
  }

  /** The joints of these names, in the config's [[joints]] order. */
  public static JointChain of(String... names) {
    if (names == null) throw new IllegalArgumentException("joint names is null");
    return of(Arrays.asList(names.clone()));
  }

  /**
   * The joints of these names, in the config's [[joints]] order: 1 to MAX_JOINTS names, each
   * non-empty printable ASCII, no name twice (IllegalArgumentException otherwise).
   */
  public static JointChain of(List<String> names) {
    if (names == null) throw new IllegalArgumentException("joint names is null");
    if (names.isEmpty() || names.size() > MAX_JOINTS) {
      throw new IllegalArgumentException(names.size() + " joints " + names + ": a robot has 1 to " + MAX_JOINTS);
    }
    List<String> copy = new ArrayList<>(names.size());
    for (String name : names) {
      if ("".equals(name)) throw new IllegalArgumentException("joint " + copy.size() + " has an empty name");
      Checks.ascii("joint " + copy.size() + " name", name);
      if (copy.contains(name)) {
        throw new IllegalArgumentException("joint name \"" + name + "\" is given twice in " + names);
      }
      copy.add(name);
    }
    return new JointChain(List.copyOf(copy));
  }

  /** How many joints: the length of every pose, state and setpoint message of this robot. */
  public int count() {
    return names.size();
  }

  /** The names, by index (unmodifiable). */
  public List<String> names() {
    return names;
  }

  /** The name of joint index. */
  public String name(int index) {
    return names.get(checkIndex(index));
  }

  /** The index of the joint of this name (IllegalArgumentException, naming the joints, for another). */
  public int index(String name) {
    int index = names.indexOf(name);
    if (index < 0) throw new IllegalArgumentException("no joint \"" + name + "\": the joints are " + this);
    return index;
  }

  /** index itself if it is a joint's (IllegalArgumentException, naming the joints, otherwise). */
  public int checkIndex(int index) {
    if (index < 0 || index >= names.size()) {
      throw new IllegalArgumentException("no joint " + index + ": the joints are " + this);
    }
    return index;
  }

  /**
   * pose itself if it is one for these joints: named (the daemon resolves it), or one position per
   * joint. Otherwise IllegalArgumentException that says both lengths.
   */
  public Pose check(Pose pose) {
    if (pose == null) throw new IllegalArgumentException("pose is null");
    if (!pose.isNamed() && pose.positions().size() != names.size()) {
      throw new IllegalArgumentException("the pose " + pose.positions() + " has " + pose.positions().size()
          + " position" + (pose.positions().size() == 1 ? "" : "s") + " but the arm has " + names.size() + " joint"
          + (names.size() == 1 ? "" : "s") + ": " + this);
    }
    return pose;
  }

  /**
   * A pose by the joints' names, e.g. {@code arm.joints().pose(Map.of("shoulder", 0.4, "elbow",
   * 1.2))}: one position per joint (m or rad), no other name; the positions go in chain order.
   */
  public Pose pose(Map<String, Double> positionsByName) {
    if (positionsByName == null) throw new IllegalArgumentException("positions is null");
    for (String name : positionsByName.keySet()) index(name);
    List<Double> positions = new ArrayList<>(names.size());
    for (String name : names) {
      Double position = positionsByName.get(name);
      if (position == null) {
        throw new IllegalArgumentException("no position for joint \"" + name + "\" in " + positionsByName);
      }
      positions.add(position);
    }
    return Pose.of(positions.stream().mapToDouble(Double::doubleValue).toArray());
  }

  /** "0 elevator, 1 arm": each joint's index and name. */
  @Override
  public String toString() {
    StringBuilder out = new StringBuilder();
    for (int i = 0; i < names.size(); ++i) {
      if (i > 0) out.append(", ");
      out.append(i).append(' ').append(names.get(i));
    }
    return out.toString();
  }

  @Override
  public boolean equals(Object other) {
    return other instanceof JointChain chain && chain.names.equals(names);
  }

  @Override
  public int hashCode() {
    return names.hashCode();
  }
}

package cyberplanner.roborio;

/**
 * The two joints cyber-plannerd commands, by index: the order of the daemon's config [[joints]]
 * (docs/lcm.md). Joint 0 is the one nearer the robot's frame, joint 1 the one it carries (a
 * lift and the arm on it, a shoulder and its elbow, a pivot and its telescope). A prismatic joint
 * is in m and m/s, a revolute one in rad and rad/s. The library names no joint's role: the robot
 * program wires each index to its motor.
 */
public enum Joint {
  /** The config's first joint, nearer the robot's frame. */
  JOINT_0,
  /** The config's second joint, carried by joint 0. */
  JOINT_1;

  /** How many joints the messages carry. */
  public static final int COUNT = 2;

  /** The index in the messages' arrays (position[i], velocity[i], ...). */
  public int index() {
    return ordinal();
  }

  /** The joint at index 0 or 1. */
  public static Joint of(int index) {
    if (index < 0 || index >= COUNT) throw new IllegalArgumentException("joint index " + index + " is not 0 or 1");
    return values()[index];
  }
}

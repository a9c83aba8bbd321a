package cyberplanner.roborio;

/**
 * One joint as the robot program wires it: the name the daemon's config gives it ([[joints]]
 * name, checked against ARM_DAEMON_STATUS's joint_names), the motor controller that takes its
 * setpoints, and the gravity model of its hold (the kG and shape of its [drives.*] section). An
 * ArmController takes one per joint, in the config's order (docs/roborio.md, "Joints by index and
 * by name").
 */
public record ArmJoint(String name, JointOutput output, JointGravity gravity) {
  public ArmJoint {
    if (name == null || name.isEmpty()) throw new IllegalArgumentException("a joint's name is null or empty");
    Checks.ascii("joint name", name);
    if (output == null) throw new IllegalArgumentException("joint \"" + name + "\" has no output");
    if (gravity == null) {
      throw new IllegalArgumentException("joint \"" + name + "\" has no gravity model (JointGravity.NONE for none)");
    }
  }

  /** The joint of this name driven by output, held against gravity (JointGravity.NONE for none). */
  public static ArmJoint of(String name, JointOutput output, JointGravity gravity) {
    return new ArmJoint(name, output, gravity);
  }
}

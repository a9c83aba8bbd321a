package cyberplanner.roborio;

/**
 * A motor controller that takes one joint's setpoint: position, velocity and feedforward voltage.
 * An arm has one per joint (ArmJoint); the layers' TalonFxOutput and SparkOutput are two.
 */
public interface JointOutput {
  /** Position in m (prismatic joint) or rad (revolute), velocity in m/s or rad/s, feedforward in volts. */
  void apply(double position, double velocity, double feedforwardVolts);
}

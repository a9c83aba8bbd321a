package cyberplanner.roborio;

/** A motor controller that takes a joint setpoint: position, velocity and feedforward voltage. */
public interface JointOutput {
  /** Position in m (prismatic joint) or rad (revolute), velocity in m/s or rad/s, feedforward in volts. */
  void apply(double position, double velocity, double feedforwardVolts);
}

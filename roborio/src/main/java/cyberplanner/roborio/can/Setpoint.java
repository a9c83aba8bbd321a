package cyberplanner.roborio.can;

/**
 * One joint's setpoint as the frame carries it (docs/can-protocol.md, "Setpoint frame"): position
 * in m (prismatic joint) or rad (revolute), velocity in m/s or rad/s, feedforward in volts, sequence 0..255.
 */
public record Setpoint(int device, double position, double velocity, double feedforwardVolts, int sequence) {}

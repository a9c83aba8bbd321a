package cyberplanner.roborio;

/**
 * Where the robot takes cyber-plannerd's setpoints and status from: the CAN bus on the robot
 * (the layers' CanStreamSetpointSource), ARM_SETPOINT in desktop simulation (LcmSetpointSource).
 */
public interface SetpointSource {
  /** Feeds what arrived since the last call into the guard, stamped nowMicros. Main loop only. */
  void poll(SetpointGuard guard, long nowMicros);
}

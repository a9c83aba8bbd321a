package cyberplanner.roborio;

/**
 * Where the robot takes cyber-plannerd's setpoints and status from: the CAN bus on the robot
 * (the layers' CanStreamSetpointSource), ARM_SETPOINT in desktop simulation (LcmSetpointSource).
 * It feeds each joint's setpoints to the guard by the joint's index.
 */
public interface SetpointSource {
  /** Feeds what arrived since the last call into the guard, stamped nowMicros. Main loop only. */
  void poll(SetpointGuard guard, long nowMicros);

  /**
   * Throws IllegalArgumentException, saying why, if this source cannot read setpoints for these
   * joints (e.g. a CAN device table with no device for one of them). ArmController calls it when
   * it is built, so a wiring mistake shows at start-up rather than as stale setpoints.
   */
  default void checkJoints(JointChain joints) {}
}

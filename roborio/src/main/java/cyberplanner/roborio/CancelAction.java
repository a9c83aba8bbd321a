package cyberplanner.roborio;

/** What the daemon does with a cancelled goal (arm_cancel_t, channel ARM_CANCEL; docs/lcm.md). */
public enum CancelAction {
  /** Brake to rest as fast as the limits allow, then hold there. */
  HOLD(cyberplanner.arm_cancel_t.ACTION_HOLD),
  /** Stop streaming setpoints: the robot program drives the joints until the next goal. */
  RELEASE(cyberplanner.arm_cancel_t.ACTION_RELEASE);

  private final byte wire;

  CancelAction(byte wire) {
    this.wire = wire;
  }

  public byte wire() {
    return wire;
  }
}

package cyberplanner.roborio.can;

/**
 * The daemon's mode: the status frame's mode byte and the MODE_* constants of arm_setpoint_t and
 * arm_daemon_status_t (docs/can-protocol.md, docs/lcm.md).
 */
public enum DaemonMode {
  NO_STATE(0),
  HOLDING(1),
  MOVING(2),
  FAULT(3),
  ROBOT_DISABLED(4),
  /** Manual override (arm_cancel_t ACTION_RELEASE): no setpoints until the next goal. */
  RELEASED(5);

  private final int wire;

  DaemonMode(int wire) {
    this.wire = wire;
  }

  public int wire() {
    return wire;
  }

  /** Holding or moving: the daemon streams setpoints. */
  public boolean streams() {
    return this == HOLDING || this == MOVING;
  }

  /** The mode of a wire value, or null for an undefined one. */
  public static DaemonMode fromWire(int value) {
    for (DaemonMode mode : values()) {
      if (mode.wire == value) return mode;
    }
    return null;
  }
}

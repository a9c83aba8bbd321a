package cyberplanner.roborio.can;

/** The daemon's status frame (docs/can-protocol.md, "Status frame"), wire values. */
public record DaemonStatus(int device, DaemonMode mode, int requestIdLow16, int timeRemainingMs, int faultBits, int sequence) {
  public static final int FAULT_STATE_STALE = 0x01;
  public static final int FAULT_CAN_WRITE_FAILED = 0x02;
  public static final int FAULT_STREAM_OVERRUN = 0x04;
  public static final int FAULT_PLAN_FAILED = 0x08;
  public static final int FAULT_BUS_ERROR = 0x10;
}

package cyberplanner.roborio.can;

/**
 * The daemon status frame (API class 2, index 0, DLC 8, 10 Hz; docs/can-protocol.md): byte 0 mode,
 * 1-2 request id low 16 bits, 3-4 time remaining ms, 5 fault bits, 6 reserved, 7 sequence. The C++
 * codec (can/status_codec.hpp) is the source of truth; tests/vectors/can_frames.txt holds both to
 * the same vectors.
 */
public final class StatusFrame {
  public static final int LENGTH = 8;

  private StatusFrame() {}

  /** Accepts only an extended data frame with the status id (any device), DLC 8 and a defined mode. */
  public static Coded<DaemonStatus> decode(CanFrame frame) {
    CodecError problem = FrcCanId.checkDataFrame(frame, FrcCanId.STATUS_API_ID, LENGTH);
    if (problem != null) return Coded.failure(problem);
    DaemonMode mode = DaemonMode.fromWire(frame.unsignedByte(0));
    if (mode == null) return Coded.failure(CodecError.BAD_MODE);
    return Coded.of(new DaemonStatus(FrcCanId.device(frame.id()), mode, Wire.getU16(frame, 1), Wire.getU16(frame, 3),
        frame.unsignedByte(5), frame.unsignedByte(7)));
  }

  /** For simulations and tests: the frame the daemon would send. */
  public static Coded<CanFrame> encode(DaemonStatus status) {
    if (status.device() < 0 || status.device() > FrcCanId.MAX_DEVICE_NUMBER) {
      return Coded.failure(CodecError.DEVICE_OUT_OF_RANGE);
    }
    if (status.mode() == null) return Coded.failure(CodecError.BAD_MODE);
    byte[] data = new byte[LENGTH];
    data[0] = (byte) status.mode().wire();
    Wire.putLittleEndian(data, 1, 2, status.requestIdLow16());
    Wire.putLittleEndian(data, 3, 2, status.timeRemainingMs());
    data[5] = (byte) status.faultBits();
    data[7] = (byte) status.sequence();
    return Coded.of(CanFrame.extendedData(FrcCanId.teamFrameId(FrcCanId.STATUS_API_ID, status.device()), data, LENGTH));
  }

  /** The low 16 bits of a request id, as the status frame carries it (two's complement). */
  public static int requestIdLow16(long requestId) {
    return (int) (requestId & 0xFFFF);
  }
}

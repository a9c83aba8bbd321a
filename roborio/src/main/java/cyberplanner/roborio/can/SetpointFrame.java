package cyberplanner.roborio.can;

/**
 * The setpoint frame (API class 1, index 0, DLC 8; docs/can-protocol.md): bytes 0-2 position,
 * signed 24-bit at 1e-5; 3-4 velocity, int16 at 1e-3; 5-6 feedforward, int16 millivolts; 7 the
 * sequence. Little-endian. The C++ codec (can/setpoint_codec.hpp) is the source of truth;
 * tests/vectors/can_frames.txt holds both to the same vectors.
 */
public final class SetpointFrame {
  public static final int LENGTH = 8;
  public static final double POSITION_COUNTS_PER_UNIT = 1e5;
  public static final double VELOCITY_COUNTS_PER_UNIT = 1e3;
  public static final double VOLTAGE_COUNTS_PER_VOLT = 1e3;
  private static final long POSITION_MAX_COUNT = (1 << 23) - 1;
  private static final long POSITION_MIN_COUNT = -(1 << 23);

  private SetpointFrame() {}

  /** Accepts only an extended data frame with the setpoint id (any device) and DLC 8. */
  public static Coded<Setpoint> decode(CanFrame frame) {
    CodecError problem = FrcCanId.checkDataFrame(frame, FrcCanId.SETPOINT_API_ID, LENGTH);
    if (problem != null) return Coded.failure(problem);
    int position = Wire.getI24(frame, 0);
    // Division (not multiplication by 1e-5) gives the double nearest the decimal value, as in C++.
    return Coded.of(new Setpoint(FrcCanId.device(frame.id()), position / POSITION_COUNTS_PER_UNIT,
        Wire.getI16(frame, 3) / VELOCITY_COUNTS_PER_UNIT, Wire.getI16(frame, 5) / VOLTAGE_COUNTS_PER_VOLT,
        frame.unsignedByte(7)));
  }

  /** For simulations and tests: the frame the daemon would send (device 0..63, sequence taken mod 256). */
  public static Coded<CanFrame> encode(Setpoint setpoint) {
    if (setpoint.device() < 0 || setpoint.device() > FrcCanId.MAX_DEVICE_NUMBER) {
      return Coded.failure(CodecError.DEVICE_OUT_OF_RANGE);
    }
    Long position = Wire.toCounts(setpoint.position(), POSITION_COUNTS_PER_UNIT, POSITION_MIN_COUNT, POSITION_MAX_COUNT);
    if (position == null) return Coded.failure(CodecError.POSITION_OUT_OF_RANGE);
    Long velocity = Wire.toCounts(setpoint.velocity(), VELOCITY_COUNTS_PER_UNIT, Short.MIN_VALUE, Short.MAX_VALUE);
    if (velocity == null) return Coded.failure(CodecError.VELOCITY_OUT_OF_RANGE);
    Long millivolts = Wire.toCounts(setpoint.feedforwardVolts(), VOLTAGE_COUNTS_PER_VOLT, Short.MIN_VALUE, Short.MAX_VALUE);
    if (millivolts == null) return Coded.failure(CodecError.VOLTAGE_OUT_OF_RANGE);
    byte[] data = new byte[LENGTH];
    Wire.putLittleEndian(data, 0, 3, position);
    Wire.putLittleEndian(data, 3, 2, velocity);
    Wire.putLittleEndian(data, 5, 2, millivolts);
    data[7] = (byte) setpoint.sequence();
    return Coded.of(CanFrame.extendedData(FrcCanId.teamFrameId(FrcCanId.SETPOINT_API_ID, setpoint.device()), data, LENGTH));
  }
}

package cyberplanner.roborio.can;

/** Little-endian fields and the count rounding of the C++ codec (can/src/wire.hpp). */
final class Wire {
  private Wire() {}

  static int getU16(CanFrame frame, int at) {
    return frame.unsignedByte(at) | (frame.unsignedByte(at + 1) << 8);
  }

  static int getI16(CanFrame frame, int at) {
    return (short) getU16(frame, at);
  }

  static int getI24(CanFrame frame, int at) {
    int bits = frame.unsignedByte(at) | (frame.unsignedByte(at + 1) << 8) | (frame.unsignedByte(at + 2) << 16);
    return (bits << 8) >> 8;  // sign-extends bit 23
  }

  static void putLittleEndian(byte[] data, int at, int bytes, long value) {
    for (int i = 0; i < bytes; ++i) data[at + i] = (byte) (value >> (8 * i));
  }

  /**
   * value * countsPerUnit rounded to the nearest count, halves away from zero (C's llround), if it
   * lies in [min, max]; null otherwise, including NaN and infinities.
   */
  static Long toCounts(double value, double countsPerUnit, long min, long max) {
    double scaled = value * countsPerUnit;
    if (!(Math.abs(scaled) < 1e12)) return null;
    double magnitude = Math.abs(scaled);
    double whole = Math.floor(magnitude);
    long counts = (long) whole + (magnitude - whole >= 0.5 ? 1 : 0);  // exact below 2^52
    if (scaled < 0) counts = -counts;
    return counts < min || counts > max ? null : counts;
  }
}

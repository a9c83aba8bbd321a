package cyberplanner.roborio.can;

import java.util.Arrays;

/**
 * A classic CAN 2.0 frame as the decoder sees it (the C++ codec's cyber::can::Frame): the
 * arbitration id, the format and kind flags, and 0 to 8 data bytes.
 */
public record CanFrame(int id, boolean extended, boolean remote, boolean error, byte[] data) {
  public CanFrame {
    data = data.clone();
  }

  /** An extended data frame, as WPILib's CAN class delivers them. */
  public static CanFrame extendedData(int id, byte[] data, int length) {
    return new CanFrame(id, true, false, false, Arrays.copyOf(data, length));
  }

  public int length() {
    return data.length;
  }

  @Override
  public byte[] data() {
    return data.clone();
  }

  int unsignedByte(int at) {
    return data[at] & 0xFF;
  }
}

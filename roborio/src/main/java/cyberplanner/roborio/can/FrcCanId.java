package cyberplanner.roborio.can;

/**
 * FRC CAN addressing of cyber-plannerd's frames (docs/can-protocol.md, "Identifiers"): device type
 * 10 Miscellaneous, manufacturer 8 Team Use, API class 1 setpoint / 2 status, API index 0.
 */
public final class FrcCanId {
  public static final int DEVICE_TYPE_MISCELLANEOUS = 10;
  public static final int MANUFACTURER_TEAM_USE = 8;
  public static final int MAX_DEVICE_NUMBER = 63;
  public static final int SETPOINT_API_CLASS = 1;
  public static final int STATUS_API_CLASS = 2;
  public static final int API_INDEX = 0;
  /** The API ids WPILib's CAN class reads by: {@code (api_class << 4) | api_index}. */
  public static final int SETPOINT_API_ID = apiId(SETPOINT_API_CLASS, API_INDEX);
  public static final int STATUS_API_ID = apiId(STATUS_API_CLASS, API_INDEX);

  private FrcCanId() {}

  public static int apiId(int apiClass, int apiIndex) {
    return ((apiClass & 0x3F) << 4) | (apiIndex & 0x0F);
  }

  /** The 29-bit id of one of our team-use frames. */
  public static int teamFrameId(int apiId, int device) {
    return (DEVICE_TYPE_MISCELLANEOUS << 24) | (MANUFACTURER_TEAM_USE << 16) | ((apiId & 0x3FF) << 6) | (device & 0x3F);
  }

  static int device(int id) {
    return id & 0x3F;
  }

  /** True when id is one of our frames with this API id, any device. */
  static boolean isTeamFrame(int id, int apiId) {
    return (id & ~0x3F) == teamFrameId(apiId, 0);
  }

  /** The flags/id/length checks of a fixed-length extended data frame, in the C++ codec's order. */
  static CodecError checkDataFrame(CanFrame frame, int apiId, int length) {
    if (frame.error()) return CodecError.ERROR_FRAME;
    if (frame.remote()) return CodecError.REMOTE_FRAME;
    if (!frame.extended()) return CodecError.NOT_EXTENDED;
    if (!isTeamFrame(frame.id(), apiId)) return CodecError.WRONG_ID;
    if (frame.length() != length) return CodecError.WRONG_LENGTH;
    return null;
  }
}

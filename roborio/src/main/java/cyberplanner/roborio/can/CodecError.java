package cyberplanner.roborio.can;

/** Why a frame could not be encoded or decoded: the C++ codec's cyber::can::CodecError. */
public enum CodecError {
  DEVICE_OUT_OF_RANGE,
  POSITION_OUT_OF_RANGE,
  VELOCITY_OUT_OF_RANGE,
  VOLTAGE_OUT_OF_RANGE,
  BAD_MODE,
  WRONG_ID,
  NOT_EXTENDED,
  REMOTE_FRAME,
  ERROR_FRAME,
  WRONG_LENGTH;
}

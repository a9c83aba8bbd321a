#include "cyber/can/codec_error.hpp"

namespace cyber::can {

std::string_view toString(CodecError error) {
  switch (error) {
    case CodecError::kOk: return "ok";
    case CodecError::kDeviceOutOfRange: return "device number out of range (0..63)";
    case CodecError::kPositionOutOfRange:
      return "position does not fit signed 24-bit at 1e-5 (|x| <= 83.88607) or is not finite";
    case CodecError::kVelocityOutOfRange: return "velocity does not fit int16 at 1e-3 (|v| <= 32.767) or is not finite";
    case CodecError::kVoltageOutOfRange:
      return "feedforward voltage does not fit int16 millivolts (|u| <= 32.767 V) or is not finite";
    case CodecError::kBadMode: return "status mode byte is not a defined mode";
    case CodecError::kWrongId: return "frame id is not the expected message";
    case CodecError::kNotExtended: return "standard (11-bit) frame where a 29-bit id is required";
    case CodecError::kRemoteFrame: return "remote request frame where data is required";
    case CodecError::kErrorFrame: return "controller error frame where data is required";
    case CodecError::kWrongLength: return "frame length differs from the message length";
  }
  return "unknown codec error";
}

}  // namespace cyber::can

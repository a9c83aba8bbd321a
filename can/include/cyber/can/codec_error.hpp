#pragma once
// Why a frame could not be encoded or decoded: the status of the codecs' cyber::Result. Values,
// not text, so the daemon can count each kind (and the streaming path allocates nothing);
// toString gives the text for logs.

#include <string_view>

namespace cyber::can {

enum class CodecError {
  kOk,                  // encoded or decoded (the status of a value)
  kDeviceOutOfRange,    // device number > 63
  kPositionOutOfRange,  // does not fit signed 24-bit at 1e-5 (or is not finite)
  kVelocityOutOfRange,  // does not fit int16 at 1e-3 (or is not finite)
  kVoltageOutOfRange,   // does not fit int16 millivolts (or is not finite)
  kBadMode,             // status mode byte is not one of the defined modes
  kWrongId,             // the frame is not the kind the decoder was asked for
  kNotExtended,         // a standard (11-bit) frame where a 29-bit one is required
  kRemoteFrame,         // a remote request where data is required
  kErrorFrame,          // a controller error frame where data is required
  kWrongLength,         // dlc differs from the message's fixed length
};

std::string_view toString(CodecError error);

}  // namespace cyber::can

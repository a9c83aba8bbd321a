#pragma once
// Which decoder a received frame belongs to, from its id and flags alone (lengths are checked by
// the decoders, so a known id with a bad payload is counted as a decode error, not ignored).

#include <string_view>

#include "cyber/can/frame.hpp"

namespace cyber::can {

enum class FrameKind {
  kSetpoint,          // team-use misc device, API 1/0, any device number
  kStatus,            // team-use misc device, API 2/0, any device number
  kHeartbeat,         // roboRIO universal heartbeat
  kBroadcastDisable,  // arbitration id 0
  kBusError,          // error frame from the local controller
  kOther,             // anything else on the bus
};

FrameKind classify(const Frame& frame);

std::string_view toString(FrameKind kind);

}  // namespace cyber::can

#pragma once
// Error frames the kernel reports for the local CAN controller (linux/can/error.h), reduced to
// what the daemon reacts to and counts.

#include <cstdint>

#include "cyber/can/codec_error.hpp"
#include "cyber/can/frame.hpp"
#include "cyber/result.hpp"

namespace cyber::can {

struct BusError {
  bool bus_off = false;                // controller went bus-off: nothing reaches the bus
  bool controller_problem = false;     // see controller_status
  std::uint8_t controller_status = 0;  // CAN_ERR_CRTL_* bits (rx/tx overflow, warning, passive)
  bool tx_timeout = false;             // a transmission timed out in the driver
  bool restarted = false;              // controller restarted after bus-off
  bool other = false;                  // any other error class bit

  bool operator==(const BusError&) const = default;
};

// Requires frame.error; frame.id holds the error-class bits.
Result<BusError, CodecError> decodeBusError(const Frame& frame);

}  // namespace cyber::can

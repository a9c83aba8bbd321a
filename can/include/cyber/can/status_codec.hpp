#pragma once
// Daemon status frame (API class 2, index 0), 10 Hz, device = the daemon's device number:
//   byte 0    mode (Mode below)
//   bytes 1-2 active request id, low 16 bits, little-endian
//   bytes 3-4 time remaining of the active trajectory, ms, little-endian, saturating at 65535
//   byte 5    fault bits (FaultBit below)
//   byte 6    reserved, 0
//   byte 7    sequence number (wraps)

#include <cstdint>
#include <string_view>

#include "cyber/can/codec_error.hpp"
#include "cyber/can/frame.hpp"
#include "cyber/result.hpp"

namespace cyber::can {

inline constexpr std::uint8_t kStatusLength = 8;

// Same numbers as the MODE_* constants of arm_setpoint_t and arm_daemon_status_t.
enum class Mode : std::uint8_t {
  kNoState = 0,        // no fresh measured state yet: no motion
  kHolding = 1,        // at rest, streaming hold setpoints
  kMoving = 2,         // streaming a trajectory
  kFault = 3,          // stopped by a fault (fault bits say which)
  kRobotDisabled = 4,  // heartbeat says disabled, is stale, or a broadcast disable arrived
  kReleased = 5,       // manual override (ARM_CANCEL release): no setpoints until the next goal
};
// The highest defined mode: a status frame with a larger byte 0 is refused.
inline constexpr Mode kLastMode = Mode::kReleased;

// "no-state", "holding", "moving", "fault", "robot-disabled", "released".
std::string_view toString(Mode mode);

// Fault bits of byte 5. Bits 0x20, 0x40, 0x80 are reserved (sent as 0).
namespace fault {
inline constexpr std::uint8_t kStateStale = 0x01;      // measured state older than its timeout
inline constexpr std::uint8_t kCanWriteFailed = 0x02;  // a setpoint frame could not be written
inline constexpr std::uint8_t kStreamOverrun = 0x04;   // the streamer missed timer periods
inline constexpr std::uint8_t kPlanFailed = 0x08;      // the latest goal was rejected or failed
inline constexpr std::uint8_t kBusError = 0x10;        // bus-off or controller error frames seen
}  // namespace fault

// Wire values (already reduced to the frame's field widths).
struct Status {
  Mode mode = Mode::kNoState;
  std::uint16_t request_id = 0;  // low 16 bits of the active request id
  std::uint16_t time_remaining_ms = 0;
  std::uint8_t fault_bits = 0;
  std::uint8_t sequence = 0;

  bool operator==(const Status&) const = default;
};

struct DeviceStatus {
  std::uint8_t device = 0;
  Status status;
};

// Low 16 bits of a request id (two's complement, so -1 becomes 0xFFFF).
constexpr std::uint16_t requestIdLow16(std::int64_t request_id) {
  return static_cast<std::uint16_t>(static_cast<std::uint64_t>(request_id) & 0xFFFFu);
}

// Seconds to whole milliseconds, rounded up so that 0 means "nothing left"; negative and NaN give
// 0, anything from 65.535 s up gives 65535.
std::uint16_t saturateTimeRemainingMs(double seconds);

Result<Frame, CodecError> encodeStatus(std::uint8_t device, const Status& status);

// Accepts only an extended data frame with our status id (any device), dlc 8 and a defined mode.
Result<DeviceStatus, CodecError> decodeStatus(const Frame& frame);

}  // namespace cyber::can

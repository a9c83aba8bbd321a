#pragma once
// Frames the roboRIO sends that gate motion: the universal heartbeat (every 20 ms) and the
// broadcast disable.

#include "cyber/can/codec_error.hpp"
#include "cyber/can/frame.hpp"
#include "cyber/can/result.hpp"

namespace cyber::can {

inline constexpr std::uint8_t kHeartbeatLength = 8;
inline constexpr std::uint8_t kHeartbeatFlagsByte = 4;

// Bits of heartbeat byte 4, from the most significant.
namespace heartbeat_bit {
inline constexpr std::uint8_t kRedAlliance = 0x80;
inline constexpr std::uint8_t kEnabled = 0x40;
inline constexpr std::uint8_t kAutonomous = 0x20;
inline constexpr std::uint8_t kTest = 0x10;
inline constexpr std::uint8_t kSystemWatchdog = 0x08;
}  // namespace heartbeat_bit

struct Heartbeat {
  bool red_alliance = false;
  bool enabled = false;
  bool autonomous = false;
  bool test = false;
  bool system_watchdog = false;  // the roboRIO lets actuators move: the bit the motion gate uses

  bool operator==(const Heartbeat&) const = default;
};

// Accepts only an extended data frame with id 0x01011840 and dlc 8; reads byte 4 only.
Result<Heartbeat, CodecError> decodeHeartbeat(const Frame& frame);

// A heartbeat with the given flags and the other bytes 0 (for simulators and tests).
Frame encodeHeartbeat(const Heartbeat& heartbeat);

// Any non-error frame with arbitration id 0, extended or standard, whatever its length: stopping on
// either form is the safe reading of "arbitration id 0".
bool isBroadcastDisable(const Frame& frame);

// Extended id 0, no data.
Frame makeBroadcastDisable();

}  // namespace cyber::can

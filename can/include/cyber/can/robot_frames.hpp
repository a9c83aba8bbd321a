#pragma once
// Frames the robot controller sends that gate motion: the universal heartbeat (every 20 ms) and
// the broadcast disable. The roboRIO (through 2026) and Systemcore (from 2027) send the heartbeat
// with the same id and length; they differ in one bit of byte 5 (docs/can-protocol.md, "Robot
// heartbeat").

#include <cstdint>

#include "cyber/can/codec_error.hpp"
#include "cyber/can/frame.hpp"
#include "cyber/result.hpp"

namespace cyber::can {

inline constexpr std::uint8_t kHeartbeatLength = 8;

// The heartbeat is one 64-bit word sent most significant byte first, so data[7] holds its lowest
// byte. The flags are bits 24..28 of the word, which land in data[4] from its least significant
// bit up; data[5] holds bits 16..23.
inline constexpr std::uint8_t kHeartbeatFlagsByte = 4;
inline constexpr std::uint8_t kHeartbeatReplayByte = 5;

namespace heartbeat_bit {
inline constexpr std::uint8_t kRedAlliance = 0x01;
inline constexpr std::uint8_t kEnabled = 0x02;
inline constexpr std::uint8_t kAutonomous = 0x04;
inline constexpr std::uint8_t kTest = 0x08;
inline constexpr std::uint8_t kSystemWatchdog = 0x10;
// data[5]: the replay number starts at bit 2; its top bit on the roboRIO is Systemcore's FTC
// motor override flag.
inline constexpr std::uint8_t kReplayShift = 2;
inline constexpr std::uint8_t kRoboRioReplayMask = 0xFC;     // 6 bits
inline constexpr std::uint8_t kSystemcoreReplayMask = 0x7C;  // 5 bits
inline constexpr std::uint8_t kFtcMotorOverride = 0x80;      // Systemcore only
}  // namespace heartbeat_bit

// Which controller sends the heartbeat: the config's [daemon] robot_controller. The layouts cannot
// be told apart from a frame (the same bit is a replay-number bit on one, a flag on the other).
enum class HeartbeatLayout : std::uint8_t { kRoboRio, kSystemcore };

struct Heartbeat {
  bool red_alliance = false;
  bool enabled = false;
  bool autonomous = false;
  bool test = false;
  bool system_watchdog = false;     // actuators may move: the bit the motion gate uses
  std::uint8_t replay_number = 0;   // 0..63 on the roboRIO, 0..31 on Systemcore
  bool ftc_motor_override = false;  // Systemcore: a hardware client drives the motors and the
                                    // robot program is disabled; always false on the roboRIO

  bool operator==(const Heartbeat&) const = default;
};

// Accepts only an extended data frame with id 0x01011840 and dlc 8; reads bytes 4 and 5 as
// `layout` defines them.
Result<Heartbeat, CodecError> decodeHeartbeat(const Frame& frame, HeartbeatLayout layout);

// A heartbeat with the given fields and the other bytes 0 (for simulators and tests). A replay
// number wider than the layout's field is cut to it; the override flag is written only in the
// Systemcore layout.
Frame encodeHeartbeat(const Heartbeat& heartbeat, HeartbeatLayout layout = HeartbeatLayout::kRoboRio);

// Any non-error frame with arbitration id 0, extended or standard, whatever its length: stopping on
// either form is the safe reading of "arbitration id 0".
bool isBroadcastDisable(const Frame& frame);

// Extended id 0, no data.
Frame makeBroadcastDisable();

}  // namespace cyber::can

#pragma once
// Setpoint frame (API class 1, index 0): one per joint per stream period. Payload little-endian:
//   bytes 0-2 position, signed 24-bit, 1e-5 m or rad
//   bytes 3-4 velocity, int16, 1e-3 m/s or rad/s
//   bytes 5-6 feedforward voltage, int16, millivolts
//   byte  7   sequence number (per joint, wraps 255 -> 0)
// Values round to the nearest count (halves away from zero); a value whose count does not fit is
// an error, never a wrap.

#include <cstdint>
#include <limits>

#include "cyber/can/codec_error.hpp"
#include "cyber/can/frame.hpp"
#include "cyber/result.hpp"

namespace cyber::can {

inline constexpr std::uint8_t kSetpointLength = 8;
inline constexpr double kPositionCountsPerUnit = 1e5;  // counts per m (prismatic joint) or rad (revolute)
inline constexpr double kVelocityCountsPerUnit = 1e3;  // counts per m/s or rad/s
inline constexpr double kVoltageCountsPerVolt = 1e3;   // millivolts
inline constexpr std::int32_t kPositionMaxCount = (1 << 23) - 1;
inline constexpr std::int32_t kPositionMinCount = -(1 << 23);
inline constexpr std::int32_t kInt16MinCount = std::numeric_limits<std::int16_t>::min();
inline constexpr std::int32_t kInt16MaxCount = std::numeric_limits<std::int16_t>::max();

// The largest magnitude of each field that encodes with either sign (the negative range is one
// count larger), in the joint's unit: what a setpoint may be before it is an encode error.
inline constexpr double kMaxPositionMagnitude = kPositionMaxCount / kPositionCountsPerUnit;
inline constexpr double kMaxVelocityMagnitude = kInt16MaxCount / kVelocityCountsPerUnit;
inline constexpr double kMaxVoltageMagnitude = kInt16MaxCount / kVoltageCountsPerVolt;

// Position and velocity are in the joint's unit: metres (prismatic) or radians (revolute).
struct Setpoint {
  double position = 0.0;
  double velocity = 0.0;
  double feedforward_volts = 0.0;
  std::uint8_t sequence = 0;

  bool operator==(const Setpoint&) const = default;
};

struct DeviceSetpoint {
  std::uint8_t device = 0;
  Setpoint setpoint;
};

Result<Frame, CodecError> encodeSetpoint(std::uint8_t device, const Setpoint& setpoint);

// Accepts only an extended data frame with our setpoint id (any device) and dlc 8.
Result<DeviceSetpoint, CodecError> decodeSetpoint(const Frame& frame);

}  // namespace cyber::can

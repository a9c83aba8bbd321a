#pragma once
// Decoding LCM messages that arrive from the network without trusting their bytes.
//
// lcm-gen 1.3.1's decode() checks the fingerprint and each read against the buffer length, but
// it trusts length fields: a string length of INT32_MIN overflows an int and makes it read
// gigabytes past the buffer (a crash), lengths of 0 or below throw std::length_error, and an array
// count of 2^31-1 allocates gigabytes before the read fails. safeDecode() checks those fields
// first and returns the ordinary "< 0" failure instead.
//
// The checks know where the length fields sit; tests/unit/lcmtypes pins every offset below
// against freshly encoded messages, so a change to a .lcm file that moves them fails a test.

#include <cstdint>
#include <exception>

#include "cyberplanner/arm_goal_t.hpp"
#include "cyberplanner/arm_plan_status_t.hpp"
#include "cyberplanner/arm_trajectory_t.hpp"

namespace cyber::lcmtypes {

namespace detail {

// Byte offsets of the length fields (after the 8-byte fingerprint; LCM packs without padding).
// arm_goal_t: utime, request_id, elevator_m, arm_rad (4 x 8), held_coral, held_algae (2 x 1).
inline constexpr int kGoalSceneNameLengthAt = 8 + 4 * 8 + 2;
// arm_plan_status_t: utime, request_id (2 x 8), status (1).
inline constexpr int kPlanStatusReasonLengthAt = 8 + 2 * 8 + 1;
// arm_trajectory_t: utime, request_id, start_utime (3 x 8), duration_s, dt_s (2 x 8).
inline constexpr int kTrajectoryCountAt = 8 + 5 * 8;
inline constexpr int kTrajectoryArrays = 7;

// LCM writes integers big-endian.
inline bool readInt32(const void* buf, int len, int at, std::int32_t& value) {
  if (at < 0 || len - at < 4) return false;
  const auto* bytes = static_cast<const std::uint8_t*>(buf) + at;
  value = static_cast<std::int32_t>((std::uint32_t{bytes[0]} << 24) | (std::uint32_t{bytes[1]} << 16) |
                                    (std::uint32_t{bytes[2]} << 8) | std::uint32_t{bytes[3]});
  return true;
}

// The only string is last in its message: its length (with the NUL) is 1 .. remaining bytes.
inline bool stringFits(const void* buf, int len, int length_at) {
  std::int32_t length = 0;
  if (!readInt32(buf, len, length_at, length)) return false;
  return length >= 1 && length <= len - (length_at + 4);
}

inline bool lengthsFit(const cyberplanner::arm_goal_t&, const void* buf, int len) {
  return stringFits(buf, len, kGoalSceneNameLengthAt);
}

inline bool lengthsFit(const cyberplanner::arm_plan_status_t&, const void* buf, int len) {
  return stringFits(buf, len, kPlanStatusReasonLengthAt);
}

inline bool lengthsFit(const cyberplanner::arm_trajectory_t&, const void* buf, int len) {
  std::int32_t count = 0;
  if (!readInt32(buf, len, kTrajectoryCountAt, count)) return false;
  if (count < 0 || count > cyberplanner::arm_trajectory_t::MAX_SAMPLES) return false;
  return std::int64_t{kTrajectoryCountAt} + 4 + std::int64_t{count} * kTrajectoryArrays * 8 <= len;
}

// Types without strings or arrays need no pre-check.
template <class Message>
bool lengthsFit(const Message&, const void*, int) {
  return true;
}

}  // namespace detail

// Decodes buf[0, len) into out. Returns the number of bytes used, or a negative number for a
// foreign type (fingerprint mismatch), a truncated buffer or corrupt length fields. Never throws.
template <class Message>
int safeDecode(Message& out, const void* buf, int len) noexcept {
  if (buf == nullptr || len < 0) return -1;
  if (!detail::lengthsFit(out, buf, len)) return -1;
  try {
    return out.decode(buf, 0, len);
  } catch (const std::exception&) {
    return -1;
  }
}

}  // namespace cyber::lcmtypes

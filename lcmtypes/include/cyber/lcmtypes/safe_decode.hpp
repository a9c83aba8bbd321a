#pragma once
// Decoding LCM messages that arrive from the network without trusting their bytes.
//
// lcm-gen 1.3.1's decode() checks the fingerprint and each read against the buffer length, but
// it trusts length fields: a string length of INT32_MIN overflows an int and makes it read
// gigabytes past the buffer (a crash), lengths of 0 or below throw std::length_error, and an array
// count of 2^31-1 allocates gigabytes before the read fails. safeDecode() checks those fields
// first and returns the ordinary "< 0" failure instead.
//
// Every type with a string or an array is walked field by field (message version 3, docs/lcm.md).

#include <cstdint>
#include <exception>

#include "cyberplanner/arm_daemon_status_t.hpp"
#include "cyberplanner/arm_goal_t.hpp"
#include "cyberplanner/arm_plan_status_t.hpp"
#include "cyberplanner/arm_setpoint_t.hpp"
#include "cyberplanner/arm_state_t.hpp"
#include "cyberplanner/arm_trajectory_t.hpp"

namespace cyber::lcmtypes {

namespace detail {

// LCM packs fields without padding and writes integers big-endian. A Reader walks a buffer
// (after the 8-byte fingerprint) field by field, checking every length before anything uses it.
class Reader {
 public:
  Reader(const void* buf, int len) : bytes_(static_cast<const std::uint8_t*>(buf)), len_(len) {}

  bool skip(std::int64_t n) {
    if (n < 0 || len_ - at_ < n) return false;
    at_ += static_cast<int>(n);
    return true;
  }
  bool int8(std::int8_t& value) {
    if (len_ - at_ < 1) return false;
    value = static_cast<std::int8_t>(bytes_[at_]);
    ++at_;
    return true;
  }
  bool int32(std::int32_t& value) {
    if (len_ - at_ < 4) return false;
    const std::uint8_t* b = bytes_ + at_;
    value = static_cast<std::int32_t>((std::uint32_t{b[0]} << 24) | (std::uint32_t{b[1]} << 16) |
                                      (std::uint32_t{b[2]} << 8) | std::uint32_t{b[3]});
    at_ += 4;
    return true;
  }
  // A string: its length (with the NUL) is 1 .. the bytes left.
  bool string() {
    std::int32_t length = 0;
    return int32(length) && length >= 1 && skip(length);
  }
  // `rows` arrays of `count` doubles each, whose count is an int8_t field: 0 .. 127 (lcm-gen
  // resizes to the count before reading, so a negative one would throw).
  bool doubles(std::int8_t count, int rows) { return count >= 0 && skip(std::int64_t{count} * rows * 8); }
  // A variable array of strings whose count is an int8_t field: 0 .. 127 (lcm-gen resizes to the
  // count before reading, so a negative one would throw).
  bool strings(std::int8_t count) {
    if (count < 0) return false;
    for (int i = 0; i < count; ++i) {
      if (!string()) return false;
    }
    return true;
  }

 private:
  const std::uint8_t* bytes_;
  int len_;
  int at_ = 8;  // after the fingerprint
};

// The field layouts below follow lcmtypes/*.lcm; tests/unit/lcmtypes decodes freshly encoded
// messages through them, so a change to a .lcm file that moves a field fails a test.

// arm_goal_t: utime, request_id (2 x 8), pose_name, num_joints (1), position[num_joints],
// num_pieces (1), pieces[num_pieces], scene_name, scene_offset_m (8).
inline bool lengthsFit(const cyberplanner::arm_goal_t&, const void* buf, int len) {
  Reader r(buf, len);
  std::int8_t joints = 0;
  std::int8_t pieces = 0;
  return r.skip(2 * 8) && r.string() && r.int8(joints) && r.doubles(joints, 1) && r.int8(pieces) && r.strings(pieces) &&
         r.string() && r.skip(8);
}

// arm_state_t: utime (8), num_joints (1), position, velocity [num_joints], num_pieces (1),
// pieces[num_pieces].
inline bool lengthsFit(const cyberplanner::arm_state_t&, const void* buf, int len) {
  Reader r(buf, len);
  std::int8_t joints = 0;
  std::int8_t pieces = 0;
  return r.skip(8) && r.int8(joints) && r.doubles(joints, 2) && r.int8(pieces) && r.strings(pieces);
}

// arm_setpoint_t: utime (8), mode (1), request_id, trajectory_t_s (2 x 8), num_joints (1),
// position, velocity, volts [num_joints], sequence[num_joints] (bytes).
inline bool lengthsFit(const cyberplanner::arm_setpoint_t&, const void* buf, int len) {
  Reader r(buf, len);
  std::int8_t joints = 0;
  return r.skip(8 + 1 + 2 * 8) && r.int8(joints) && r.doubles(joints, 3) && r.skip(joints);
}

// arm_plan_status_t: utime, request_id (2 x 8), status (1), reason.
inline bool lengthsFit(const cyberplanner::arm_plan_status_t&, const void* buf, int len) {
  Reader r(buf, len);
  return r.skip(2 * 8 + 1) && r.string();
}

// arm_daemon_status_t: utime (8), mode (1), num_joints (1), joint_names[num_joints],
// joint_units[num_joints].
inline bool lengthsFit(const cyberplanner::arm_daemon_status_t&, const void* buf, int len) {
  Reader r(buf, len);
  std::int8_t joints = 0;
  return r.skip(8 + 1) && r.int8(joints) && r.strings(joints) && r.strings(joints);
}

// arm_trajectory_t: utime, request_id, start_utime (3 x 8), duration_s, dt_s (2 x 8), num_joints
// (1), num_samples (4), then t_s[num_samples] and position, velocity, volts
// [num_joints][num_samples]: 1 + 3 x num_joints doubles per sample.
inline constexpr int kTrajectoryRowsPerJoint = 3;
inline bool lengthsFit(const cyberplanner::arm_trajectory_t&, const void* buf, int len) {
  Reader r(buf, len);
  std::int8_t joints = 0;
  std::int32_t count = 0;
  if (!r.skip(5 * 8) || !r.int8(joints) || !r.int32(count)) return false;
  if (joints < 0 || count < 0 || count > cyberplanner::arm_trajectory_t::MAX_SAMPLES) return false;
  return r.skip(std::int64_t{count} * (1 + kTrajectoryRowsPerJoint * joints) * 8);
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

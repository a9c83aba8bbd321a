#pragma once
// Decoding LCM messages that arrive from the network without trusting their bytes.
//
// lcm-gen 1.3.1's decode() checks the fingerprint and every read against the buffer length,
// but it sizes strings and arrays from length fields before checking them: a string length of 0
// or less throws std::length_error, and an array count of 2^31-1 asks for gigabytes before the
// read fails. safeDecode() turns both into the ordinary "< 0" failure.

#include <cstdint>
#include <cstring>
#include <exception>

#include "cyberplanner/arm_trajectory_t.hpp"

namespace cyber::lcmtypes {

namespace detail {

// arm_trajectory_t is the only type with arrays: check num_samples before decode() resizes.
// Its offset is the fingerprint (8) + utime, request_id, start_utime (3 x 8) + duration_s,
// dt_s (2 x 8); the byte-level test in tests/unit/lcmtypes pins this layout.
inline bool arraysFit(const cyberplanner::arm_trajectory_t& /*type*/, const void* buf, int len) {
  constexpr int kCountOffset = 8 + 3 * 8 + 2 * 8;
  constexpr int kArrays = 7;
  if (len < kCountOffset + 4) return false;
  const auto* bytes = static_cast<const std::uint8_t*>(buf) + kCountOffset;
  const std::int32_t count = static_cast<std::int32_t>(
      (std::uint32_t{bytes[0]} << 24) | (std::uint32_t{bytes[1]} << 16) |
      (std::uint32_t{bytes[2]} << 8) | std::uint32_t{bytes[3]});
  if (count < 0 || count > cyberplanner::arm_trajectory_t::MAX_SAMPLES) return false;
  return static_cast<std::int64_t>(kCountOffset) + 4 + std::int64_t{count} * kArrays * 8 <= len;
}

// Types without arrays need no pre-check.
template <class Message>
bool arraysFit(const Message& /*type*/, const void* /*buf*/, int /*len*/) {
  return true;
}

}  // namespace detail

// Decodes buf[0, len) into out. Returns the number of bytes used, or a negative number for a
// foreign type (fingerprint mismatch), a truncated buffer or corrupt length fields. Never throws.
template <class Message>
int safeDecode(Message& out, const void* buf, int len) noexcept {
  if (buf == nullptr || len < 0) return -1;
  if (!detail::arraysFit(out, buf, len)) return -1;
  try {
    return out.decode(buf, 0, len);
  } catch (const std::exception&) {
    return -1;
  }
}

}  // namespace cyber::lcmtypes

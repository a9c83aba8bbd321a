#pragma once
// Little-endian field access and the checks every data-frame decoder shares.

#include <cmath>
#include <cstdint>
#include <optional>

#include "cyber/can/codec_error.hpp"
#include "cyber/can/frame.hpp"

namespace cyber::can::wire {

inline void putU16(Frame& frame, int at, std::uint16_t value) {
  frame.data[at] = static_cast<std::uint8_t>(value & 0xFFu);
  frame.data[at + 1] = static_cast<std::uint8_t>(value >> 8);
}

inline std::uint16_t getU16(const Frame& frame, int at) {
  return static_cast<std::uint16_t>(frame.data[at] | (frame.data[at + 1] << 8));
}

inline void putI16(Frame& frame, int at, std::int16_t value) { putU16(frame, at, static_cast<std::uint16_t>(value)); }

inline std::int16_t getI16(const Frame& frame, int at) { return static_cast<std::int16_t>(getU16(frame, at)); }

// Two's complement in 24 bits.
inline void putI24(Frame& frame, int at, std::int32_t value) {
  const auto bits = static_cast<std::uint32_t>(value) & 0xFFFFFFu;
  frame.data[at] = static_cast<std::uint8_t>(bits & 0xFFu);
  frame.data[at + 1] = static_cast<std::uint8_t>((bits >> 8) & 0xFFu);
  frame.data[at + 2] = static_cast<std::uint8_t>(bits >> 16);
}

inline std::int32_t getI24(const Frame& frame, int at) {
  const std::uint32_t bits = std::uint32_t{frame.data[at]} | (std::uint32_t{frame.data[at + 1]} << 8) |
                             (std::uint32_t{frame.data[at + 2]} << 16);
  // Sign-extend bit 23 without relying on implementation-defined shifts.
  return (bits & 0x800000u) != 0 ? static_cast<std::int32_t>(bits) - (1 << 24) : static_cast<std::int32_t>(bits);
}

// value * counts_per_unit rounded to the nearest count (halves away from zero), if it lies in
// [min_count, max_count]; nullopt otherwise, including NaN and infinities.
inline std::optional<std::int32_t> toCounts(double value, double counts_per_unit, std::int32_t min_count,
                                            std::int32_t max_count) {
  const double scaled = value * counts_per_unit;
  // Also rejects NaN; the bound keeps llround far from its own overflow.
  if (!(std::fabs(scaled) < 1e12)) return std::nullopt;
  const long long counts = std::llround(scaled);
  if (counts < min_count || counts > max_count) return std::nullopt;
  return static_cast<std::int32_t>(counts);
}

// The flags/id/length checks of a fixed-length extended data frame.
inline std::optional<CodecError> checkDataFrame(const Frame& frame, bool id_matches, std::uint8_t length) {
  if (frame.error) return CodecError::kErrorFrame;
  if (frame.remote) return CodecError::kRemoteFrame;
  if (!frame.extended) return CodecError::kNotExtended;
  if (!id_matches) return CodecError::kWrongId;
  if (frame.dlc != length) return CodecError::kWrongLength;
  return std::nullopt;
}

}  // namespace cyber::can::wire

#pragma once
// Random well-formed CAN frames of every flavour (standard, extended, remote, error) for the
// round-trip property tests.

#include <cstdint>
#include <random>

#include "cyber/can/frame.hpp"

namespace cyber::can::test {

template <class Rng>
Frame randomFrame(Rng& rng) {
  std::uniform_int_distribution<int> flavour(0, 3), dlc(0, 8), byte(0, 255);
  std::uniform_int_distribution<std::uint32_t> eff(0, kExtendedIdMask), sff(0, kStandardIdMask);
  Frame frame;
  switch (flavour(rng)) {
    case 0: frame.id = sff(rng); break;
    case 1:
      frame.id = eff(rng);
      frame.extended = true;
      break;
    case 2:
      frame.id = sff(rng);
      frame.remote = true;
      break;
    default:
      frame.id = eff(rng) & 0x1FFu;
      frame.error = true;
      break;
  }
  frame.dlc = static_cast<std::uint8_t>(dlc(rng));
  if (!frame.remote) {
    for (std::uint8_t i = 0; i < frame.dlc; ++i) frame.data[i] = static_cast<std::uint8_t>(byte(rng));
  }
  return frame;
}

}  // namespace cyber::can::test

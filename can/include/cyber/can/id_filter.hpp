#pragma once
// Receive filters for a CAN socket: which data frames the kernel hands to us.

#include <linux/can.h>

#include <cstdint>

#include "cyber/can/frame.hpp"

namespace cyber::can {

// Receive data frames whose id matches `id` on the bits of `mask`, in one format only.
struct IdFilter {
  std::uint32_t id = 0;
  std::uint32_t mask = 0;
  bool extended = true;

  static IdFilter exact(std::uint32_t id, bool extended) {
    return IdFilter{id, extended ? kExtendedIdMask : kStandardIdMask, extended};
  }
  bool operator==(const IdFilter&) const = default;
};

// The kernel's form: the format flag and RTR are part of the match, so a filter passes only data
// frames of its own format.
can_filter toKernelFilter(const IdFilter& filter);

// The kernel's matching rule for one filter (received_id & mask) == (filter_id & mask), applied
// to a frame: lets tests check filters without a CAN socket.
bool kernelFilterMatches(const can_filter& filter, const Frame& frame);

}  // namespace cyber::can

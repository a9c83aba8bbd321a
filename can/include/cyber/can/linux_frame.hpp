#pragma once
// Conversion between Frame and the kernel's struct can_frame (flags in the id's top bits).

#include <linux/can.h>

#include "cyber/can/codec_error.hpp"
#include "cyber/can/frame.hpp"
#include "cyber/result.hpp"

namespace cyber::can {

// Id bits beyond the frame's format and a dlc above 8 are clipped: isWellFormed() frames map
// one-to-one.
can_frame toLinuxFrame(const Frame& frame);

// A dlc above 8 is kWrongLength. Bytes past dlc come back as 0.
Result<Frame, CodecError> fromLinuxFrame(const can_frame& raw);

}  // namespace cyber::can

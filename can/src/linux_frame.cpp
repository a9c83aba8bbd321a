#include "cyber/can/linux_frame.hpp"

#include <algorithm>
#include <cstring>

namespace cyber::can {

can_frame toLinuxFrame(const Frame& frame) {
  can_frame raw;
  std::memset(&raw, 0, sizeof raw);
  if (frame.error) {
    raw.can_id = (frame.id & CAN_ERR_MASK) | CAN_ERR_FLAG;
  } else if (frame.extended) {
    raw.can_id = (frame.id & CAN_EFF_MASK) | CAN_EFF_FLAG;
  } else {
    raw.can_id = frame.id & CAN_SFF_MASK;
  }
  if (frame.remote && !frame.error) raw.can_id |= CAN_RTR_FLAG;
  raw.len = std::min<std::uint8_t>(frame.dlc, CAN_MAX_DLEN);
  if (!frame.remote) std::memcpy(raw.data, frame.data.data(), raw.len);
  return raw;
}

Result<Frame, CodecError> fromLinuxFrame(const can_frame& raw) {
  if (raw.len > CAN_MAX_DLEN) return CodecError::kWrongLength;
  Frame frame;
  frame.error = (raw.can_id & CAN_ERR_FLAG) != 0;
  frame.extended = !frame.error && (raw.can_id & CAN_EFF_FLAG) != 0;
  frame.remote = !frame.error && (raw.can_id & CAN_RTR_FLAG) != 0;
  if (frame.error) {
    frame.id = raw.can_id & CAN_ERR_MASK;
  } else {
    frame.id = raw.can_id & (frame.extended ? CAN_EFF_MASK : CAN_SFF_MASK);
  }
  frame.dlc = raw.len;
  if (!frame.remote) std::memcpy(frame.data.data(), raw.data, raw.len);
  return frame;
}

}  // namespace cyber::can

#include "cyber/can/bus_error.hpp"

#include <linux/can/error.h>

namespace cyber::can {

Result<BusError, CodecError> decodeBusError(const Frame& frame) {
  if (!frame.error) return CodecError::kWrongId;
  constexpr std::uint32_t kKnown = CAN_ERR_BUSOFF | CAN_ERR_CRTL | CAN_ERR_TX_TIMEOUT | CAN_ERR_RESTARTED;
  BusError out;
  out.bus_off = (frame.id & CAN_ERR_BUSOFF) != 0;
  out.controller_problem = (frame.id & CAN_ERR_CRTL) != 0;
  // The kernel puts the controller status in data[1] of a CAN_ERR_CRTL frame.
  if (out.controller_problem && frame.dlc >= 2) out.controller_status = frame.data[1];
  out.tx_timeout = (frame.id & CAN_ERR_TX_TIMEOUT) != 0;
  out.restarted = (frame.id & CAN_ERR_RESTARTED) != 0;
  out.other = (frame.id & ~kKnown) != 0;
  return out;
}

}  // namespace cyber::can

#include "cyber/can/id_filter.hpp"

#include "cyber/can/frc_id.hpp"
#include "cyber/can/linux_frame.hpp"

namespace cyber::can {

can_filter toKernelFilter(const IdFilter& filter) {
  can_filter out{};
  if (filter.extended) {
    out.can_id = (filter.id & CAN_EFF_MASK) | CAN_EFF_FLAG;
    out.can_mask = (filter.mask & CAN_EFF_MASK) | CAN_EFF_FLAG | CAN_RTR_FLAG;
  } else {
    out.can_id = filter.id & CAN_SFF_MASK;
    out.can_mask = (filter.mask & CAN_SFF_MASK) | CAN_EFF_FLAG | CAN_RTR_FLAG;
  }
  return out;
}

bool kernelFilterMatches(const can_filter& filter, const Frame& frame) {
  // Error frames bypass CAN_RAW_FILTER (they go through CAN_RAW_ERR_FILTER instead).
  if (frame.error) return false;
  const canid_t received = toLinuxFrame(frame).can_id;
  return (received & filter.can_mask) == (filter.can_id & filter.can_mask);
}

}  // namespace cyber::can

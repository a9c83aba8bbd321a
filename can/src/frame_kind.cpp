#include "cyber/can/frame_kind.hpp"

#include "cyber/can/frc_id.hpp"
#include "cyber/can/robot_frames.hpp"

namespace cyber::can {

FrameKind classify(const Frame& frame) {
  if (frame.error) return FrameKind::kBusError;
  if (isBroadcastDisable(frame)) return FrameKind::kBroadcastDisable;
  if (!frame.extended) return FrameKind::kOther;
  if (frame.id == kHeartbeatId) return FrameKind::kHeartbeat;
  const FrcId id = unpackFrcId(frame.id);
  if (id.device_type != kDeviceTypeMiscellaneous || id.manufacturer != kManufacturerTeamUse) {
    return FrameKind::kOther;
  }
  if (id.api_class == kSetpointApiClass && id.api_index == kSetpointApiIndex) {
    return FrameKind::kSetpoint;
  }
  if (id.api_class == kStatusApiClass && id.api_index == kStatusApiIndex) {
    return FrameKind::kStatus;
  }
  return FrameKind::kOther;
}

std::string_view toString(FrameKind kind) {
  switch (kind) {
    case FrameKind::kSetpoint: return "setpoint";
    case FrameKind::kStatus: return "status";
    case FrameKind::kHeartbeat: return "heartbeat";
    case FrameKind::kBroadcastDisable: return "disable";
    case FrameKind::kBusError: return "bus-error";
    case FrameKind::kOther: return "other";
  }
  return "other";
}

}  // namespace cyber::can

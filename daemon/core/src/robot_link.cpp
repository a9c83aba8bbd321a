#include "cyber/daemon/robot_link.hpp"

#include "cyber/can/frame_kind.hpp"
#include "cyber/can/robot_frames.hpp"

namespace cyber::daemon {

int drainRobotFrames(RobotFrameSource& source, MonoNs now, RobotLink& link, int max_frames) {
  int count = 0;
  can::Frame frame;
  while (count < max_frames && source.read(frame).ok()) {
    ++count;
    switch (can::classify(frame)) {
      case can::FrameKind::kHeartbeat: {
        const auto heartbeat = can::decodeHeartbeat(frame, link.heartbeat_layout);
        if (!heartbeat) {
          ++link.bad_heartbeats;
          break;
        }
        link.heartbeat_ns = now;
        link.heartbeat_watchdog = heartbeat.value().system_watchdog;
        link.heartbeat_motor_override = heartbeat.value().ftc_motor_override;
        break;
      }
      case can::FrameKind::kBroadcastDisable:
        link.broadcast_disable_ns = now;
        ++link.broadcast_disable_count;
        break;
      default: break;
    }
  }
  return count;
}

void applyRobotLink(const RobotLink& link, RobotInputs& inputs) {
  inputs.heartbeat_ns = link.heartbeat_ns;
  inputs.heartbeat_watchdog = link.heartbeat_watchdog;
  inputs.heartbeat_motor_override = link.heartbeat_motor_override;
  inputs.broadcast_disable_ns = link.broadcast_disable_ns;
  inputs.broadcast_disable_count = link.broadcast_disable_count;
}

}  // namespace cyber::daemon

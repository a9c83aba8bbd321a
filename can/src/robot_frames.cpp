#include "cyber/can/robot_frames.hpp"

#include "cyber/can/frc_id.hpp"
#include "wire.hpp"

namespace cyber::can {
namespace {

std::uint8_t replayMask(HeartbeatLayout layout) {
  return layout == HeartbeatLayout::kSystemcore ? heartbeat_bit::kSystemcoreReplayMask
                                                : heartbeat_bit::kRoboRioReplayMask;
}

}  // namespace

Result<Heartbeat, CodecError> decodeHeartbeat(const Frame& frame, HeartbeatLayout layout) {
  if (const auto problem = wire::checkDataFrame(frame, frame.id == kHeartbeatId, kHeartbeatLength)) {
    return *problem;
  }
  const std::uint8_t flags = frame.data[kHeartbeatFlagsByte];
  const std::uint8_t replay = frame.data[kHeartbeatReplayByte];
  Heartbeat out;
  out.red_alliance = (flags & heartbeat_bit::kRedAlliance) != 0;
  out.enabled = (flags & heartbeat_bit::kEnabled) != 0;
  out.autonomous = (flags & heartbeat_bit::kAutonomous) != 0;
  out.test = (flags & heartbeat_bit::kTest) != 0;
  out.system_watchdog = (flags & heartbeat_bit::kSystemWatchdog) != 0;
  out.replay_number = static_cast<std::uint8_t>((replay & replayMask(layout)) >> heartbeat_bit::kReplayShift);
  out.ftc_motor_override = layout == HeartbeatLayout::kSystemcore && (replay & heartbeat_bit::kFtcMotorOverride) != 0;
  return out;
}

Frame encodeHeartbeat(const Heartbeat& heartbeat, HeartbeatLayout layout) {
  Frame frame;
  frame.id = kHeartbeatId;
  frame.extended = true;
  frame.dlc = kHeartbeatLength;
  std::uint8_t flags = 0;
  if (heartbeat.red_alliance) flags |= heartbeat_bit::kRedAlliance;
  if (heartbeat.enabled) flags |= heartbeat_bit::kEnabled;
  if (heartbeat.autonomous) flags |= heartbeat_bit::kAutonomous;
  if (heartbeat.test) flags |= heartbeat_bit::kTest;
  if (heartbeat.system_watchdog) flags |= heartbeat_bit::kSystemWatchdog;
  frame.data[kHeartbeatFlagsByte] = flags;
  auto replay =
      static_cast<std::uint8_t>((heartbeat.replay_number << heartbeat_bit::kReplayShift) & replayMask(layout));
  if (layout == HeartbeatLayout::kSystemcore && heartbeat.ftc_motor_override) {
    replay |= heartbeat_bit::kFtcMotorOverride;
  }
  frame.data[kHeartbeatReplayByte] = replay;
  return frame;
}

bool isBroadcastDisable(const Frame& frame) { return !frame.error && frame.id == kBroadcastDisableId; }

Frame makeBroadcastDisable() {
  Frame frame;
  frame.id = kBroadcastDisableId;
  frame.extended = true;
  return frame;
}

}  // namespace cyber::can

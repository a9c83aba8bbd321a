#include "cyber/daemon/motion_gate.hpp"

namespace cyber::daemon {

std::string_view toString(GateReason reason) {
  switch (reason) {
    case GateReason::kOpen: return "open";
    case GateReason::kNoState: return "no ARM_STATE received yet";
    case GateReason::kStateStale: return "ARM_STATE is stale";
    case GateReason::kRobotDisabled: return "robot disabled (heartbeat without system-watchdog bit)";
    case GateReason::kMotorOverride: return "robot disabled (heartbeat with FTC motor override)";
    case GateReason::kNoHeartbeat: return "no fresh roboRIO heartbeat";
    case GateReason::kBroadcastDisable: return "broadcast disable received";
    case GateReason::kFault: return "fault: a setpoint was not finite or did not fit its frame";
    case GateReason::kReleased: return "released: the robot program drives the joints (ARM_CANCEL, manual override)";
  }
  return "unknown";
}

bool isRobotDisabledReason(GateReason reason) {
  return reason == GateReason::kRobotDisabled || reason == GateReason::kMotorOverride ||
         reason == GateReason::kNoHeartbeat || reason == GateReason::kBroadcastDisable;
}

GateVerdict evaluateGate(const RobotInputs& inputs, MonoNs now, const GateSettings& settings) {
  const MonoNs heartbeat_timeout = secondsToNs(settings.heartbeat_timeout_s);
  const bool disabled_seen = inputs.broadcast_disable_ns != kNever;
  if (settings.require_robot_enabled) {
    if (inputs.heartbeat_ns == kNever || now - inputs.heartbeat_ns >= heartbeat_timeout) {
      return {GateReason::kNoHeartbeat};
    }
    // The override first: with it the watchdog bit can be set for a hardware client's motors
    // while the robot program, and so this daemon, must stay still.
    if (inputs.heartbeat_motor_override) return {GateReason::kMotorOverride};
    if (!inputs.heartbeat_watchdog) return {GateReason::kRobotDisabled};
    // Only an enabled heartbeat that arrived after the disable lifts it.
    if (disabled_seen && inputs.broadcast_disable_ns >= inputs.heartbeat_ns) return {GateReason::kBroadcastDisable};
  } else if (disabled_seen && now - inputs.broadcast_disable_ns < heartbeat_timeout) {
    return {GateReason::kBroadcastDisable};
  }
  if (inputs.state_ns == kNever) return {GateReason::kNoState};
  if (now - inputs.state_ns > secondsToNs(settings.state_timeout_s)) return {GateReason::kStateStale};
  if (isReleased(inputs.release_generation)) return {GateReason::kReleased};
  return {GateReason::kOpen};
}

}  // namespace cyber::daemon

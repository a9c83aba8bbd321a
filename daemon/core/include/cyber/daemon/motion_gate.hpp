#pragma once
// The motion gate: may the daemon stream motion at "now"? Closed without fresh measured state,
// while the robot controller's heartbeat lacks the system-watchdog bit, carries Systemcore's FTC
// motor override or is older than its timeout, after a broadcast disable, and while the robot
// program has taken the joints over (ARM_CANCEL's release) (docs/design.md, "The motion gate";
// docs/can-protocol.md, "Robot heartbeat").

#include <cstdint>
#include <string_view>

#include "cyber/daemon/mono_time.hpp"
#include "cyber/planner.hpp"

namespace cyber::daemon {

struct GateSettings {
  double state_timeout_s = 0.25;
  double heartbeat_timeout_s = 0.1;
  bool require_robot_enabled = true;  // false: bench use without a roboRIO
};

// Latest inputs as the event loop saw them (receive times on the monotonic clock).
struct RobotInputs {
  MonoNs state_ns = kNever;  // arrival of the latest valid ARM_STATE
  planner::JointVector measured_q;
  planner::JointVector measured_qdot;
  MonoNs heartbeat_ns = kNever;           // arrival of the latest robot controller heartbeat
  bool heartbeat_watchdog = false;        // its system-watchdog bit
  bool heartbeat_motor_override = false;  // its FTC motor override flag (Systemcore only)
  MonoNs broadcast_disable_ns = kNever;   // arrival of the latest broadcast disable
  // Broadcast disables seen so far. The streamer latches each new one as an event: a disable
  // followed within a period by an enabled heartbeat would otherwise be lifted before any tick saw it.
  std::uint32_t broadcast_disable_count = 0;
  // The manual override (ARM_CANCEL's release): odd while the robot program drives the joints.
  // The coordinator bumps it when a release begins and when the next goal ends it; the streamer
  // latches every change as a stop, so a release that ends before any tick saw it still restarts
  // the stream from the measured position.
  std::uint32_t release_generation = 0;
};

enum class GateReason {
  kOpen,
  kNoState,           // no ARM_STATE yet
  kStateStale,        // the latest ARM_STATE is older than state_timeout_s
  kRobotDisabled,     // the latest heartbeat lacks the system-watchdog bit
  kMotorOverride,     // the latest heartbeat has the FTC motor override flag: a hardware client
                      // drives the motors and the robot program is disabled
  kNoHeartbeat,       // no heartbeat, or it is older than heartbeat_timeout_s
  kBroadcastDisable,  // a broadcast disable arrived and no enabled heartbeat since
  kFault,             // not from evaluateGate: the streamer stopped on a setpoint it could not send
  kReleased,          // manual override: the robot program drives the joints until the next goal
};

std::string_view toString(GateReason reason);

// True for reasons that mean "the robot is disabled" (CAN status mode 4) rather than "no state".
bool isRobotDisabledReason(GateReason reason);

[[nodiscard]] inline bool isReleased(std::uint32_t release_generation) { return release_generation % 2 == 1; }

struct GateVerdict {
  GateReason reason = GateReason::kNoState;
  [[nodiscard]] bool open() const { return reason == GateReason::kOpen; }
};

// With require_robot_enabled, a broadcast disable holds until a heartbeat with the watchdog bit
// (and no motor override) arrives after it; without (bench use, no roboRIO), until
// heartbeat_timeout_s has passed since the latest disable. Robot reasons take precedence over state
// reasons, and both over a release (kReleased means "everything else is open", so a goal that ends
// the release may be accepted).
GateVerdict evaluateGate(const RobotInputs& inputs, MonoNs now, const GateSettings& settings);

}  // namespace cyber::daemon

#pragma once
// What the daemon says about itself, on the event-loop thread: ARM_DAEMON_STATUS (docs/lcm.md),
// the service manager's STATUS= line (once a second), the fault bits of the CAN status frame, the
// ARM_SETPOINT echo, and the log line for broadcast disables the streamer read.

#include <cstdint>
#include <string>

#include "cyber/daemon/io/can_input.hpp"
#include "cyber/daemon/io/goal_handler.hpp"
#include "cyber/daemon/io/lcm_bridge.hpp"
#include "cyber/daemon/io/lcm_input.hpp"
#include "cyber/daemon/io/log_throttle.hpp"
#include "cyber/daemon/io/streamer_thread.hpp"
#include "cyber/daemon/motion_gate.hpp"
#include "cyber/planner.hpp"

namespace cyber::daemon::io {

// The error counters every report sums the same way (ARM_DAEMON_STATUS, STATUS=).
struct ErrorTotals {
  std::int64_t can = 0;     // failed writes, controller error frames, failed reads
  std::int64_t decode = 0;  // undecodable LCM messages, bad states, heartbeats with a bad payload
};

class StatusPublisher {
 public:
  // What the reports are made of; everything must outlive the publisher. can_input is null
  // without a CAN bus.
  struct Sources {
    StreamerChannels& channels;
    const GoalHandler& goals;
    const LcmInput& lcm_input;
    const CanInput* can_input;
    LcmBridge& bridge;
    const planner::RobotModel& robot;  // joint names and units for ARM_DAEMON_STATUS
  };

  StatusPublisher(const Sources& sources, const GateSettings& gate) : s_(sources), gate_(gate) {}

  // At status_rate_hz: fault bits for the streamer, the disable log line, STATUS= (1 Hz) and
  // ARM_DAEMON_STATUS.
  void onStatusTimer(MonoNs now);
  // The setpoints of the latest tick on ARM_SETPOINT, if new: at setpoint_echo_rate_hz, and after
  // every tick with setpoint_echo_full_rate.
  void publishSetpointEcho();
  // One line for systemd's STATUS=.
  [[nodiscard]] std::string serviceStatus() const;

 private:
  [[nodiscard]] ErrorTotals errorTotals(const StreamSnapshot& snapshot) const;
  [[nodiscard]] bool robotEnabled(const StreamSnapshot& snapshot, MonoNs now) const;
  [[nodiscard]] std::uint8_t faultBits(MonoNs now) const;
  void logRobotLink(const StreamSnapshot& snapshot, MonoNs now);
  void publishDaemonStatus(const StreamSnapshot& snapshot, MonoNs now);

  Sources s_;
  GateSettings gate_;
  MonoNs last_service_status_ns_ = kNever;
  std::int64_t last_echo_tick_ = 0;
  std::uint32_t disables_logged_ = 0;
  std::int64_t lost_logged_ = 0;
  ThrottledWarning disable_warning_;
};

}  // namespace cyber::daemon::io

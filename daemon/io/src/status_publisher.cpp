#include "cyber/daemon/io/status_publisher.hpp"

#include <algorithm>

#include <spdlog/spdlog.h>

#include "cyber/can/status_codec.hpp"
#include "cyber/daemon/io/clock_pair.hpp"
#include "cyber/daemon/io/lcm_messages.hpp"
#include "cyber/notify/notifier.hpp"
#include "cyberplanner/arm_daemon_status_t.hpp"

namespace cyber::daemon::io {

namespace {

constexpr MonoNs kSecond = 1'000'000'000;

// Age of a receive stamp at `now` (ms), -1 before the first. The receiving thread can stamp a
// message after `now` was read, so a fresh one would come out a fraction of a millisecond below
// zero (once -0.2 ms in CI's daemon_integration_wall_clock_jump): it is fresh, age 0.
double ageMs(MonoNs now, MonoNs stamp) { return stamp == kNever ? -1.0 : std::max(0.0, nsToMs(now - stamp)); }

}  // namespace

ErrorTotals StatusPublisher::errorTotals(const StreamSnapshot& snapshot) const {
  ErrorTotals totals;
  totals.can = s_.channels.write_failures.load(std::memory_order_relaxed) +
               (s_.can_input != nullptr ? s_.can_input->errors() : 0);
  totals.decode = s_.lcm_input.decodeErrors() + snapshot.robot_link.bad_heartbeats;
  return totals;
}

std::string StatusPublisher::serviceStatus() const {
  const StreamSnapshot snapshot = s_.channels.snapshot.load();
  const CoordinatorCounters& c = s_.goals.counters();
  const ErrorTotals errors = errorTotals(snapshot);
  return fmt::format("{}, request {}, {} goals, {} plans, {} failed or rejected, {} CAN errors, {} decode errors",
                     toString(snapshot.mode), snapshot.request_id, c.goals_received, c.plans_succeeded,
                     c.plans_failed + c.goals_rejected, errors.can, errors.decode);
}

bool StatusPublisher::robotEnabled(const StreamSnapshot& snapshot, MonoNs now) const {
  if (!gate_.require_robot_enabled) return true;
  const GateReason reason =
      evaluateGate(gateInputs(s_.lcm_input.state(), snapshot.robot_link, s_.channels.release_generation.load()), now,
                   gate_)
          .reason;
  return !isRobotDisabledReason(reason);
}

std::uint8_t StatusPublisher::faultBits(MonoNs now) const {
  std::uint8_t bits = 0;
  if (s_.goals.lastGoalFailed()) bits |= can::fault::kPlanFailed;
  if (s_.can_input != nullptr && s_.can_input->busErrorWithin(now, kSecond)) bits |= can::fault::kBusError;
  const MonoNs overrun = s_.channels.last_overrun_ns.load(std::memory_order_relaxed);
  if (overrun != kNever && now - overrun < kSecond) bits |= can::fault::kStreamOverrun;
  return bits;
}

void StatusPublisher::logRobotLink(const StreamSnapshot& snapshot, MonoNs now) {
  if (snapshot.robot_link.broadcast_disable_count != disables_logged_) {
    disables_logged_ = snapshot.robot_link.broadcast_disable_count;
    disable_warning_.warn(now, "broadcast disable received: motion stopped");
  }
  const std::int64_t lost = s_.channels.lost_messages.load(std::memory_order_relaxed);
  if (lost != lost_logged_) {
    spdlog::error("{} streamer messages lost to full queues ({} in all)", lost - lost_logged_, lost);
    lost_logged_ = lost;
  }
}

void StatusPublisher::onStatusTimer(MonoNs now) {
  if (last_service_status_ns_ == kNever || now - last_service_status_ns_ >= kSecond) {
    last_service_status_ns_ = now;
    notify::notifyStatus(serviceStatus());
  }
  s_.channels.fault_bits.store(faultBits(now), std::memory_order_relaxed);
  const StreamSnapshot snapshot = s_.channels.snapshot.load();
  logRobotLink(snapshot, now);
  publishDaemonStatus(snapshot, now);
}

void StatusPublisher::publishDaemonStatus(const StreamSnapshot& snapshot, MonoNs now) {
  const CoordinatorCounters& c = s_.goals.counters();
  const ErrorTotals errors = errorTotals(snapshot);
  const MonoNs state_ns = s_.lcm_input.state().state_ns;
  const MonoNs heartbeat_ns = snapshot.robot_link.heartbeat_ns;
  const LatencyHistogram& plan_times = s_.goals.planTimes();
  const LatencyHistogram& jitter = s_.channels.jitter;
  cyberplanner::arm_daemon_status_t m{};
  m.utime = wallMicros();
  m.mode = static_cast<std::int8_t>(snapshot.mode);
  m.num_joints = static_cast<std::int8_t>(s_.robot.joints.size());
  for (const planner::ChainJoint& joint : s_.robot.joints) {
    m.joint_names.push_back(joint.name);
    m.joint_units.push_back(planner::unitName(joint.type));
  }
  m.robot_enabled = robotEnabled(snapshot, now);
  m.motion_allowed = snapshot.ticks > 0 && snapshot.gate_reason == GateReason::kOpen;
  m.active_request_id = snapshot.request_id;
  m.state_age_ms = ageMs(now, state_ns);
  m.heartbeat_age_ms = ageMs(now, heartbeat_ns);
  m.goals_received = c.goals_received;
  m.plans_succeeded = c.plans_succeeded;
  m.plans_failed = c.plans_failed + c.goals_rejected;
  m.frames_sent = s_.channels.frames_sent.load(std::memory_order_relaxed);
  m.can_errors = errors.can;
  m.decode_errors = errors.decode;
  m.stream_overruns = s_.channels.overruns.load(std::memory_order_relaxed);
  m.publish_failures = s_.bridge.publishFailures();
  m.plan_time_p50_ms = plan_times.percentileUs(0.5) * 1e-3;
  m.plan_time_p99_ms = plan_times.percentileUs(0.99) * 1e-3;
  m.plan_time_max_ms = plan_times.maxUs() * 1e-3;
  m.stream_jitter_p50_us = jitter.percentileUs(0.5);
  m.stream_jitter_p99_us = jitter.percentileUs(0.99);
  m.stream_jitter_max_us = jitter.maxUs();
  m.realtime_priority = s_.channels.realtime_priority.load(std::memory_order_relaxed);
  s_.bridge.publish(s_.bridge.channels().daemon_status, m);
}

void StatusPublisher::publishSetpointEcho() {
  const StreamSnapshot snapshot = s_.channels.snapshot.load();
  if (snapshot.ticks == last_echo_tick_ || !snapshot.setpoints_written) return;
  last_echo_tick_ = snapshot.ticks;
  s_.bridge.publish(s_.bridge.channels().setpoint, setpointMessage(snapshot, static_cast<int>(s_.robot.joints.size()),
                                                                   wallMicrosAt(snapshot.time_ns, readClockPair())));
}

}  // namespace cyber::daemon::io

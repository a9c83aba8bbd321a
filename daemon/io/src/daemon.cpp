#include "cyber/daemon/io/daemon.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <unistd.h>

#include "cyber/can/frame_kind.hpp"
#include "cyber/can/robot_frames.hpp"
#include "cyber/can/status_codec.hpp"
#include "cyber/daemon/io/lcm_messages.hpp"
#include "cyber/daemon/io/logging.hpp"
#include "cyber/notify/notifier.hpp"
#include "cyberplanner/arm_daemon_status_t.hpp"

namespace cyber::daemon::io {

namespace {

constexpr MonoNs kSecond = 1'000'000'000;
constexpr double kShutdownHoldS = 0.05;     // hold setpoints streamed before exiting
constexpr double kWorkerJoinS = 0.3;        // a plan still running after this is abandoned
constexpr int kMaxMessagesPerWake = 64;
constexpr MonoNs kTrajectoryInterval = 100'000'000;  // at most 10 ARM_TRAJECTORY messages per second

GateSettings gateOf(const DaemonOptions& options) {
  GateSettings gate;
  gate.state_timeout_s = options.settings.state_timeout_s;
  gate.heartbeat_timeout_s = options.settings.heartbeat_timeout_s;
  // In simulation there is no roboRIO and so no heartbeat: the robot-enabled gate is open.
  gate.require_robot_enabled = options.settings.require_robot_enabled && !options.simulate_can;
  return gate;
}

StreamerSettings streamerSettingsOf(const DaemonOptions& options) {
  StreamerSettings settings;
  settings.gate = gateOf(options);
  return settings;
}

MonoNs periodOf(double rate_hz) { return secondsToNs(1.0 / rate_hz); }

FrameWriterSettings writerSettingsOf(const DaemonOptions& options) {
  const auto& s = options.settings;
  FrameWriterSettings out;
  out.elevator_device = static_cast<std::uint8_t>(s.devices.elevator);
  out.arm_device = static_cast<std::uint8_t>(s.devices.arm);
  out.status_device = static_cast<std::uint8_t>(s.devices.status);
  out.status_every_ticks = std::max(1, static_cast<int>(std::lround(s.stream_rate_hz / s.status_rate_hz)));
  return out;
}

CoordinatorSettings coordinatorSettingsOf(const DaemonOptions& options) {
  CoordinatorSettings out;
  out.planning_budget_s = options.settings.planning_budget_s;
  out.stream_period_s = 1.0 / options.settings.stream_rate_hz;
  return out;
}

// liblcm reports why it cannot open a URL on stderr itself, over several lines. Capture that text
// so a start-up failure stays one line, with LCM's reason in it.
std::unique_ptr<lcm::LCM> openLcm(const std::string& url) {
  std::FILE* capture = std::tmpfile();
  const int saved = capture != nullptr ? ::dup(STDERR_FILENO) : -1;
  if (saved >= 0) {
    std::fflush(stderr);
    ::dup2(::fileno(capture), STDERR_FILENO);
  }
  auto lcm = std::make_unique<lcm::LCM>(url);
  std::string text;
  if (saved >= 0) {
    std::fflush(stderr);
    ::dup2(saved, STDERR_FILENO);
    ::close(saved);
    std::rewind(capture);
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, capture) != nullptr) {
      std::string line(buffer);
      while (!line.empty() && (line.back() == '\n' || line.back() == '\r' || line.back() == ' ')) line.pop_back();
      if (line.empty()) continue;
      text += (text.empty() ? "" : "; ") + line;
    }
  }
  if (capture != nullptr) std::fclose(capture);
  if (!lcm->good()) {
    throw StartupError("cannot open LCM at '" + url + "'" + (text.empty() ? std::string() : ": " + text));
  }
  if (!text.empty()) spdlog::warn("LCM: {}", text);
  return lcm;
}

std::optional<can::CanSocket> openCan(const DaemonOptions& options,
                                      const can::SocketOptions& socket_options = can::SocketOptions{}) {
  if (options.simulate_can) return std::nullopt;
  auto socket = can::CanSocket::open(options.settings.can_interface, socket_options);
  if (!socket) throw StartupError(socket.error().message);
  return std::move(socket).value();
}

}  // namespace

Daemon::Daemon(const planner::RobotModel& robot, const DaemonOptions& options, const PlanningService& planning,
               const SignalFd* signals)
    : robot_(robot),
      options_(options),
      gate_(gateOf(options)),
      signals_(signals),
      lcm_(openLcm(options.settings.lcm_url)),
      can_(openCan(options)),
      port_(can_ ? std::unique_ptr<CanPort>(std::make_unique<SocketCanPort>(*can_))
                 : std::unique_ptr<CanPort>(std::make_unique<DiscardingCanPort>())),
      robot_can_(openCan(options, robotLinkSocketOptions())),
      robot_source_(robot_can_ ? std::make_unique<SocketRobotFrameSource>(*robot_can_) : nullptr),
      streamer_(HoldModel(robot), streamerSettingsOf(options)),
      writer_(*port_, writerSettingsOf(options)),
      streamer_thread_(channels_, streamer_, writer_, periodOf(options.settings.stream_rate_hz)),
      worker_(planning),
      coordinator_(robot, coordinatorSettingsOf(options), *this) {
  bridge_ = std::make_unique<LcmBridge>(
      *lcm_, options_.settings.channels,
      LcmBridge::Callbacks{[this](const cyberplanner::arm_goal_t& m) { onGoalMessage(m); },
                           [this](const cyberplanner::arm_state_t& m) { onStateMessage(m); },
                           [this](const std::string& channel, int size) { onUndecodable(channel, size); }});
  streamer_thread_.setRobotFrameSource(robot_source_.get());
  loop_.add(bridge_->fd(), [this] { bridge_->handleReady(kMaxMessagesPerWake); });
  if (can_) loop_.add(can_->fd(), [this] { onCanReadable(); });
  if (signals_ != nullptr) loop_.add(signals_->fd(), [this] { onSignal(); });
  loop_.add(worker_.wakeFd(), [this] { onPlanDone(); });
  // setpoint_echo_full_rate: the streamer wakes the loop after every tick, which echoes it.
  channels_.wake_on_setpoints.store(options_.settings.setpoint_echo_full_rate);
  loop_.add(channels_.wake.fd(), [this] {
    onStreamerWake();
    if (options_.settings.setpoint_echo_full_rate) publishSetpointEcho();
  });
  loop_.add(status_timer_.fd(), [this] { onStatusTimer(); });
  loop_.add(echo_timer_.fd(), [this] { onEchoTimer(); });
  loop_.add(exit_timer_.fd(), [this] {
    exit_timer_.consume();
    loop_.stop();
  });
}

Daemon::~Daemon() {
  streamer_thread_.stop();
  Program* program = nullptr;
  while (channels_.retired.pop(program)) delete program;
  delete channels_.offered.exchange(nullptr);
}

int Daemon::run() {
  const auto& s = options_.settings;
  spdlog::info("cyber-plannerd: robot '{}', LCM '{}', CAN {}, {} Hz streaming, robot-enabled gate {}", robot_.name,
               s.lcm_url, options_.simulate_can ? "none (simulation: frames are discarded)" : "'" + s.can_interface + "'",
               s.stream_rate_hz, gate_.require_robot_enabled ? "on" : "off");
  // Opens the service manager's socket here, not on the streaming thread (no-op without systemd).
  notify::notifyStatus("starting");
  const auto watchdog = notify::watchdogInterval();
  if (watchdog.count() > 0) {
    const MonoNs interval = static_cast<MonoNs>(watchdog.count()) * 1000;
    channels_.watchdog_period_ns.store(std::min(interval / 2, MonoNs{500'000'000}));
    channels_.loop_alive_limit_ns.store(interval / 2);
  }
  channels_.loop_alive_ns.store(monotonicNow());
  worker_.start();
  streamer_thread_.start();
  const MonoNs now = monotonicNow();
  status_timer_.startPeriodic(now + periodOf(s.status_rate_hz), periodOf(s.status_rate_hz));
  echo_timer_.startPeriodic(now + periodOf(s.setpoint_echo_rate_hz), periodOf(s.setpoint_echo_rate_hz));

  // LCM is open and the CAN socket bound (both in the constructor): ready.
  notify::notifyReadyWithStatus(serviceStatus());
  loop_.run();

  streamer_thread_.stop();
  onStreamerWake();  // last events and retired programs
  if (!worker_.stop(kWorkerJoinS)) {
    spdlog::warn("a plan is still running after {} s; exiting without waiting for it", kWorkerJoinS);
    flushLogging();
    std::_Exit(0);
  }
  spdlog::info("cyber-plannerd stopped: {} goals, {} plans, {} CAN frames sent", coordinator_.counters().goals_received,
               coordinator_.counters().plans_succeeded, channels_.frames_sent.load());
  flushLogging();
  return 0;
}

void Daemon::requestStop() {
  loop_.post([this] { beginShutdown("stop requested"); });
}

void Daemon::beginShutdown(const char* why) {
  if (shutting_down_) return;
  shutting_down_ = true;
  spdlog::info("{}: holding the commanded position and exiting", why);
  notify::notifyStopping();
  channels_.stop_requested.store(true);
  coordinator_.onShutdown(monotonicNow());
  exit_timer_.startOnce(monotonicNow() + secondsToNs(kShutdownHoldS));
}

void Daemon::onSignal() {
  while (const int signal = signals_->take()) beginShutdown(signal == SIGINT ? "SIGINT" : "SIGTERM");
}

// ---- inputs ----

void Daemon::onGoalMessage(const cyberplanner::arm_goal_t& message) { handleGoal(goalFromMessage(message)); }

void Daemon::handleGoal(const GoalRequest& goal) {
  const MonoNs now = monotonicNow();
  goal_received_ns_[goal.request_id] = now;
  spdlog::debug("goal {}: elevator {} m, arm {} rad, coral {}, algae {}, scene '{}'", goal.request_id, goal.elevator_m,
                goal.arm_rad, goal.held_coral, goal.held_algae, goal.scene_name);
  coordinator_.onGoal(goal, now, evaluateGate(inputs_.toInputs(), now, gate_));
}

void Daemon::onStateMessage(const cyberplanner::arm_state_t& message) {
  const MonoNs now = monotonicNow();
  const auto state = stateFromMessage(message, robot_);
  if (!state) {
    ++counters_.bad_states;
    std::int64_t suppressed = 0;
    if (state_log_.allow(now, suppressed)) {
      spdlog::warn("ignoring ARM_STATE with non-finite or out-of-range values (elevator {} m, arm {} rad){}",
                   message.elevator_m, message.arm_rad,
                   suppressed > 0 ? fmt::format("; {} more since the last report", suppressed) : "");
    }
    return;
  }
  inputs_.state_ns = now;
  inputs_.measured_q[0] = state->q[0];
  inputs_.measured_q[1] = state->q[1];
  inputs_.measured_qdot[0] = state->qdot[0];
  inputs_.measured_qdot[1] = state->qdot[1];
  storeInputs();
}

void Daemon::onUndecodable(const std::string& channel, int size) {
  ++counters_.lcm_decode_errors;
  std::int64_t suppressed = 0;
  if (decode_log_.allow(monotonicNow(), suppressed)) {
    spdlog::warn("undecodable message on {} ({} bytes: wrong type, fingerprint or corrupt){}", channel, size,
                 suppressed > 0 ? fmt::format("; {} more since the last report", suppressed) : "");
  }
}

void Daemon::onCanReadable() {
  const MonoNs now = monotonicNow();
  can::Frame frame;
  for (int i = 0; i < kMaxMessagesPerWake; ++i) {
    const can::IoResult result = can_->read(frame);
    if (result.status == can::IoStatus::kWouldBlock) return;
    if (!result.ok()) {
      ++counters_.can_read_errors;
      std::int64_t suppressed = 0;
      if (can_log_.allow(now, suppressed)) spdlog::warn("CAN read failed: {}; retrying in 100 ms", result.message());
      // An interface that is down keeps the socket readable with an error: stop polling it for a
      // moment instead of spinning (the status timer adds it back).
      loop_.remove(can_->fd());
      can_suspended_until_ = now + kSecond / 10;
      return;
    }
    switch (can::classify(frame)) {
      case can::FrameKind::kHeartbeat: {
        const auto heartbeat = can::decodeHeartbeat(frame);
        if (!heartbeat) {
          ++counters_.can_decode_errors;
          break;
        }
        inputs_.heartbeat_ns = now;
        inputs_.heartbeat_watchdog = heartbeat.value().system_watchdog;
        storeInputs();
        break;
      }
      case can::FrameKind::kBroadcastDisable: {
        inputs_.broadcast_disable_ns = now;
        storeInputs();
        ++counters_.broadcast_disables;
        std::int64_t suppressed = 0;
        if (disable_log_.allow(now, suppressed)) spdlog::warn("broadcast disable received: motion stopped");
        break;
      }
      case can::FrameKind::kBusError: {
        ++counters_.bus_errors;
        bus_error_ns_ = now;
        std::int64_t suppressed = 0;
        if (can_log_.allow(now, suppressed)) spdlog::warn("CAN controller error frame (id 0x{:08x})", frame.id);
        break;
      }
      default:
        break;  // the receive filter passes only the frames above
    }
  }
}

// ---- worker and streamer ----

void Daemon::onPlanDone() {
  auto outcome = worker_.takeResult();
  if (!outcome) return;
  plan_times_.record(outcome->plan_time_s * 1e6);
  coordinator_.onPlanResult(outcome->job_id, std::move(outcome->result), outcome->plan_time_s, monotonicNow());
}

void Daemon::onStreamerWake() {
  channels_.wake.drain();
  const MonoNs now = monotonicNow();
  StreamEvent event;
  while (channels_.events.pop(event)) {
    if (event.kind == StreamEventKind::kExecuting) {
      if (auto it = goal_received_ns_.find(event.request_id); it != goal_received_ns_.end()) {
        goal_latency_.record(nsToSeconds(event.time_ns - it->second) * 1e6);
        spdlog::debug("request {}: first setpoint {:.2f} ms after the goal arrived", event.request_id,
                      nsToMs(event.time_ns - it->second));
      }
    } else if (event.kind == StreamEventKind::kStopped) {
      spdlog::warn("motion stopped: {}", toString(event.gate_reason));
    } else if (event.kind == StreamEventKind::kHolding) {
      spdlog::info("holding elevator {:.4f} m, arm {:.4f} rad ({})", event.position[0], event.position[1],
                   event.hold_cause == HoldCause::kShutdown ? "shutdown" : "motion allowed");
    }
    coordinator_.onStreamEvent(event, now);
  }
  Program* program = nullptr;
  while (channels_.retired.pop(program)) delete program;
  WriteNotice notice;
  while (channels_.notices.pop(notice)) {
    if (notice.started) {
      can::IoResult result;
      result.status = notice.status;
      result.error_number = notice.error_number;
      spdlog::warn("CAN write failed: {}; dropping frames until the interface takes them again", result.message());
    } else {
      spdlog::info("CAN writes recovered; {} frames were dropped", notice.failures);
    }
  }
}

// ---- CoordinatorSink ----

void Daemon::publishStatus(const StatusUpdate& update) {
  bridge_->publish(bridge_->channels().plan_status, statusMessage(update, wallMicros()));
  const auto id = update.request_id;
  switch (update.status) {
    case GoalStatus::kRejected:
    case GoalStatus::kFailed: {
      last_goal_failed_ = true;
      std::int64_t suppressed = 0;
      if (reject_log_.allow(monotonicNow(), suppressed)) {
        spdlog::warn("request {} {}: {}{}", id, toString(update.status), update.reason,
                     suppressed > 0 ? fmt::format(" ({} more rejected or failed since the last report)", suppressed)
                                    : "");
      }
      break;
    }
    case GoalStatus::kExecuting:
      spdlog::info("request {} executing ({:.3f} s, planned in {:.1f} ms)", id, update.duration_s, update.times_ms.total);
      break;
    case GoalStatus::kDone:
      last_goal_failed_ = false;
      spdlog::info("request {} done", id);
      break;
    default:
      spdlog::debug("request {} {}{}{}", id, toString(update.status), update.reason.empty() ? "" : ": ", update.reason);
      break;
  }
  if (isFinal(update.status)) goal_received_ns_.erase(id);
}

void Daemon::publishTrajectory(std::int64_t request_id, const SharedSetpointSource& trajectory, MonoNs start_ns) {
  pending_trajectory_ = PendingTrajectory{request_id, trajectory, start_ns};
  flushTrajectory(monotonicNow(), false);
}

void Daemon::flushTrajectory(MonoNs now, bool force) {
  if (!pending_trajectory_) return;
  if (!force && last_trajectory_ns_ != kNever && now - last_trajectory_ns_ < kTrajectoryInterval) return;
  last_trajectory_ns_ = now;
  const std::int64_t wall = wallMicros();
  const PendingTrajectory pending = std::move(*pending_trajectory_);
  pending_trajectory_.reset();
  bridge_->publish(bridge_->channels().trajectory,
                   trajectoryMessage(pending.request_id, *pending.trajectory,
                                     monoToWallMicros(pending.start_ns, now, wall), options_.settings.trajectory_step_s,
                                     wall));
}

void Daemon::startPlanning(const PlanJob& job) { worker_.submit(job); }

void Daemon::postProgram(std::unique_ptr<Program> program) {
  const std::uint64_t id = program->id;
  Program* unread = channels_.offered.exchange(program.release(), std::memory_order_acq_rel);
  if (unread != nullptr) {
    // The coordinator waits for each program's answer, so this is not expected; answer for the
    // streamer so the coordinator does not wait forever.
    spdlog::error("program {} replaced program {} before the streamer read it", id, unread->id);
    StreamEvent rejected;
    rejected.kind = StreamEventKind::kRejected;
    rejected.program_id = unread->id;
    rejected.reject_reason = RejectReason::kStaleBase;
    delete unread;
    loop_.post([this, rejected] { coordinator_.onStreamEvent(rejected, monotonicNow()); });
  }
}

void Daemon::note(NoteLevel level, const std::string& text) {
  switch (level) {
    case NoteLevel::kDebug: spdlog::debug("{}", text); break;
    case NoteLevel::kInfo: spdlog::info("{}", text); break;
    case NoteLevel::kWarn: spdlog::warn("{}", text); break;
  }
}

// ---- periodic ----

std::string Daemon::serviceStatus() const {
  const StreamSnapshot snapshot = channels_.snapshot.load();
  const CoordinatorCounters& c = coordinator_.counters();
  return fmt::format("{}, request {}, {} goals, {} plans, {} failed or rejected, {} CAN errors, {} decode errors",
                     toString(snapshot.mode), snapshot.request_id, c.goals_received, c.plans_succeeded,
                     c.plans_failed + c.goals_rejected,
                     channels_.write_failures.load() + counters_.bus_errors + counters_.can_read_errors,
                     counters_.lcm_decode_errors + counters_.bad_states + counters_.can_decode_errors);
}

bool Daemon::robotEnabled(MonoNs now) const {
  if (!gate_.require_robot_enabled) return true;
  const GateReason reason = evaluateGate(inputs_.toInputs(), now, gate_).reason;
  return !isRobotDisabledReason(reason);
}

void Daemon::onStatusTimer() {
  status_timer_.consume();
  const MonoNs now = monotonicNow();
  channels_.loop_alive_ns.store(now, std::memory_order_relaxed);
  coordinator_.onTimer(now);
  flushTrajectory(now, false);
  if (last_service_status_ns_ == kNever || now - last_service_status_ns_ >= kSecond) {
    last_service_status_ns_ = now;
    notify::notifyStatus(serviceStatus());
  }
  if (can_ && can_suspended_until_ != kNever && now >= can_suspended_until_) {
    can_suspended_until_ = kNever;
    loop_.add(can_->fd(), [this] { onCanReadable(); });
  }
  std::uint8_t bits = 0;
  if (last_goal_failed_) bits |= can::fault::kPlanFailed;
  if (bus_error_ns_ != kNever && now - bus_error_ns_ < kSecond) bits |= can::fault::kBusError;
  const MonoNs overrun = channels_.last_overrun_ns.load(std::memory_order_relaxed);
  if (overrun != kNever && now - overrun < kSecond) bits |= can::fault::kStreamOverrun;
  channels_.fault_bits.store(bits, std::memory_order_relaxed);
  publishDaemonStatus(now);
}

void Daemon::publishDaemonStatus(MonoNs now) {
  const StreamSnapshot snapshot = channels_.snapshot.load();
  const CoordinatorCounters& c = coordinator_.counters();
  cyberplanner::arm_daemon_status_t m{};
  m.utime = wallMicros();
  m.mode = static_cast<std::int8_t>(snapshot.mode);
  m.robot_enabled = robotEnabled(now);
  m.motion_allowed = snapshot.ticks > 0 && snapshot.gate_reason == GateReason::kOpen;
  m.active_request_id = snapshot.request_id;
  m.state_age_ms = inputs_.state_ns == kNever ? -1.0 : nsToMs(now - inputs_.state_ns);
  // The gate's view when the streamer reads the bus itself (robot_link.hpp), else the loop's.
  const MonoNs heartbeat_ns = robot_source_ && snapshot.ticks > 0 ? snapshot.heartbeat_ns : inputs_.heartbeat_ns;
  m.heartbeat_age_ms = heartbeat_ns == kNever ? -1.0 : nsToMs(now - heartbeat_ns);
  m.goals_received = c.goals_received;
  m.plans_succeeded = c.plans_succeeded;
  m.plans_failed = c.plans_failed + c.goals_rejected;
  m.frames_sent = channels_.frames_sent.load(std::memory_order_relaxed);
  m.can_errors = channels_.write_failures.load(std::memory_order_relaxed) + counters_.bus_errors +
                 counters_.can_read_errors;
  m.decode_errors = counters_.lcm_decode_errors + counters_.bad_states + counters_.can_decode_errors;
  m.stream_overruns = channels_.overruns.load(std::memory_order_relaxed);
  m.publish_failures = bridge_->publishFailures();
  m.plan_time_p50_ms = plan_times_.percentileUs(0.5) * 1e-3;
  m.plan_time_p99_ms = plan_times_.percentileUs(0.99) * 1e-3;
  m.plan_time_max_ms = plan_times_.maxUs() * 1e-3;
  m.stream_jitter_p50_us = channels_.jitter.percentileUs(0.5);
  m.stream_jitter_p99_us = channels_.jitter.percentileUs(0.99);
  m.stream_jitter_max_us = channels_.jitter.maxUs();
  bridge_->publish(bridge_->channels().daemon_status, m);
}

void Daemon::onEchoTimer() {
  echo_timer_.consume();
  publishSetpointEcho();
}

void Daemon::publishSetpointEcho() {
  const StreamSnapshot snapshot = channels_.snapshot.load();
  if (snapshot.ticks == last_echo_tick_ || !snapshot.setpoints_written) return;
  last_echo_tick_ = snapshot.ticks;
  const MonoNs now = monotonicNow();
  const std::int64_t wall = wallMicros();
  bridge_->publish(bridge_->channels().setpoint,
                   setpointMessage(snapshot, monoToWallMicros(snapshot.time_ns, now, wall)));
}

}  // namespace cyber::daemon::io

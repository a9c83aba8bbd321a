#include "cyber/daemon/io/daemon.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <unistd.h>

#include "cyber/daemon/io/can_socket_ports.hpp"
#include "cyber/daemon/io/logging.hpp"
#include "cyber/daemon/io/monotonic_clock.hpp"
#include "cyber/daemon/io/named_poses.hpp"
#include "cyber/notify/notifier.hpp"

namespace cyber::daemon::io {

namespace {

constexpr double kShutdownHoldS = 0.05;  // hold setpoints streamed before exiting
constexpr double kWorkerJoinS = 0.3;     // a plan still running after this is abandoned
constexpr int kMaxMessagesPerWake = 64;

GateSettings gateOf(const DaemonOptions& options) {
  GateSettings gate;
  gate.state_timeout_s = options.settings.state_timeout_s;
  gate.heartbeat_timeout_s = options.settings.heartbeat_timeout_s;
  // In simulation there is no roboRIO and so no heartbeat: the robot-enabled gate is open.
  gate.require_robot_enabled = options.settings.require_robot_enabled && !options.simulate_can;
  return gate;
}

can::HeartbeatLayout heartbeatLayoutOf(config::RobotController controller) {
  return controller == config::RobotController::kRoboRio ? can::HeartbeatLayout::kRoboRio
                                                         : can::HeartbeatLayout::kSystemcore;
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
  out.joint_devices = planner::PerJoint<std::uint8_t>();
  for (const int device : s.devices.joints) out.joint_devices.push_back(static_cast<std::uint8_t>(device));
  out.status_device = static_cast<std::uint8_t>(s.devices.status);
  out.status_every_ticks = std::max(1, static_cast<int>(std::lround(s.stream_rate_hz / s.status_rate_hz)));
  return out;
}

GoalHandler::Settings goalSettingsOf(const DaemonOptions& options, const planner::RobotModel& robot) {
  GoalHandler::Settings out;
  out.coordinator.poses = namedPoseLookup(options.poses, robot);
  out.coordinator.planning_budget_s = options.settings.planning_budget_s;
  out.coordinator.max_budget_s = options.settings.max_planning_budget_s;
  out.coordinator.stream_period_s = 1.0 / options.settings.stream_rate_hz;
  out.trajectory_step_s = options.settings.trajectory_step_s;
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

std::optional<can::CanSocket> openCan(const DaemonOptions& options, const can::SocketOptions& socket_options) {
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
      state_lcm_(openLcm(options.settings.lcm_url)),
      can_(openCan(options, eventLoopSocketOptions())),
      port_(can_ ? std::unique_ptr<CanPort>(std::make_unique<SocketCanPort>(*can_))
                 : std::unique_ptr<CanPort>(std::make_unique<DiscardingCanPort>())),
      robot_can_(openCan(options, robotLinkSocketOptions())),
      robot_source_(robot_can_ ? std::make_unique<SocketRobotFrameSource>(*robot_can_) : nullptr),
      streamer_(HoldModel(robot), streamerSettingsOf(options)),
      writer_(*port_, writerSettingsOf(options)),
      streamer_thread_(channels_, streamer_, writer_, periodOf(options.settings.stream_rate_hz)),
      worker_(planning),
      lcm_input_(
          robot_, channels_, [this](const GoalRequest& goal) { onGoal(goal); },
          [this](const CancelRequest& cancel) { goals_.onCancel(cancel, monotonicNow()); }),
      bridge_(*lcm_, options.settings.channels, lcm_input_.callbacks()),
      state_receiver_(*state_lcm_, options.settings.channels.state, lcm_input_),
      goals_(robot_, goalSettingsOf(options, robot_), bridge_, worker_, channels_, loop_),
      can_input_(can_ ? std::make_unique<CanInput>(*can_, loop_) : nullptr),
      status_(StatusPublisher::Sources{channels_, goals_, lcm_input_, can_input_.get(), bridge_, robot_}, gate_) {
  streamer_thread_.setRobotFrameSource(robot_source_.get(), heartbeatLayoutOf(options.settings.robot_controller));
  loop_.add(bridge_.fd(), [this] { bridge_.handleReady(kMaxMessagesPerWake); });
  if (signals_ != nullptr) loop_.add(signals_->fd(), [this] { onSignal(); });
  loop_.add(worker_.wakeFd(), [this] { goals_.onPlanDone(); });
  // setpoint_echo_full_rate: the streamer wakes the loop after every tick, which echoes it.
  channels_.wake_on_setpoints.store(options_.settings.setpoint_echo_full_rate);
  loop_.add(channels_.wake.fd(), [this] {
    onStreamerWake();
    if (options_.settings.setpoint_echo_full_rate) status_.publishSetpointEcho();
  });
  loop_.add(status_timer_.fd(), [this] { onStatusTimer(); });
  loop_.add(echo_timer_.fd(), [this] {
    echo_timer_.consume();
    status_.publishSetpointEcho();
  });
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
  spdlog::info(
      "cyber-plannerd: robot '{}', LCM '{}', CAN {}, {} Hz streaming, robot-enabled gate {}", robot_.name, s.lcm_url,
      options_.simulate_can ? "none (simulation: frames are discarded)" : "'" + s.can_interface + "'", s.stream_rate_hz,
      !gate_.require_robot_enabled                              ? "off"
      : s.robot_controller == config::RobotController::kRoboRio ? "on (roboRIO heartbeat)"
                                                                : "on (Systemcore heartbeat)");
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
  const int state_priority = state_receiver_.start();
  if (state_priority > 0) {
    spdlog::info("ARM_STATE is received at SCHED_FIFO priority {}", state_priority);
  } else {
    spdlog::info(
        "real-time priority refused: ARM_STATE is received at normal priority, so a busy machine can "
        "make it look stale (docs/operations.md, \"Real-time priority\")");
  }
  const MonoNs now = monotonicNow();
  status_timer_.startPeriodic(now + periodOf(s.status_rate_hz), periodOf(s.status_rate_hz));
  echo_timer_.startPeriodic(now + periodOf(s.setpoint_echo_rate_hz), periodOf(s.setpoint_echo_rate_hz));

  // LCM is open and the CAN socket bound (both in the constructor): ready.
  notify::notifyReadyWithStatus(status_.serviceStatus());
  loop_.run();

  streamer_thread_.stop();
  onStreamerWake();  // last events and retired programs
  if (!worker_.stop(kWorkerJoinS)) {
    spdlog::warn("a plan is still running after {} s; exiting without waiting for it", kWorkerJoinS);
    flushLogging();
    std::_Exit(0);
  }
  spdlog::info("cyber-plannerd stopped: {} goals, {} plans, {} CAN frames sent", goals_.counters().goals_received,
               goals_.counters().plans_succeeded, channels_.frames_sent.load());
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
  goals_.onShutdown(monotonicNow());
  exit_timer_.startOnce(monotonicNow() + secondsToNs(kShutdownHoldS));
}

void Daemon::onSignal() {
  while (const int signal = signals_->take()) beginShutdown(signal == SIGINT ? "SIGINT" : "SIGTERM");
}

// Goals are admitted on the gate as the streamer last read the robot link (robot_link.hpp).
void Daemon::onGoal(const GoalRequest& goal) {
  const MonoNs now = monotonicNow();
  const RobotInputs inputs =
      gateInputs(lcm_input_.state(), channels_.snapshot.load().robot_link, channels_.release_generation.load());
  goals_.onGoal(goal, now, evaluateGate(inputs, now, gate_));
}

void Daemon::onStreamerWake() {
  channels_.wake.drain();
  const MonoNs now = monotonicNow();
  StreamEvent event;
  while (channels_.events.pop(event)) goals_.onStreamEvent(event, now);
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

void Daemon::onStatusTimer() {
  status_timer_.consume();
  const MonoNs now = monotonicNow();
  channels_.loop_alive_ns.store(now, std::memory_order_relaxed);
  goals_.onTimer(now);
  if (can_input_) can_input_->onTimer(now);
  status_.onStatusTimer(now);
}

}  // namespace cyber::daemon::io

#include "sim_runner.hpp"

#include <array>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

#include <time.h>
#include <unistd.h>

#include "cyber/can/frc_id.hpp"
#include "cyber/can/robot_frames.hpp"
#include "cyber/can/setpoint_codec.hpp"
#include "cyber/plant/control_lines.hpp"
#include "cyber/plant/freeze_clock.hpp"
#include "cyber/plant/joint_streams.hpp"
#include "cyber/plant/state_log.hpp"
#include "cyber/posix/fd.hpp"
#include "cyberplanner/arm_state_t.hpp"

namespace cyber::plant {

namespace {

constexpr double kHeartbeatPeriod_s = 0.020;
constexpr double kFreezeTolerance_s = 0.020;

// Seconds on CLOCK_MONOTONIC (the timers' clock) and microseconds on CLOCK_REALTIME (LCM's utime).
double monotonicSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

std::int64_t realtimeMicros() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

std::int64_t toNs(double seconds) { return static_cast<std::int64_t>(std::llround(seconds * 1e9)); }

enum Tag : std::uint64_t { kCanTag, kHeartbeatTag, kStateTag, kFaultTag, kSignalTag, kControlTag };

class Runner {
 public:
  Runner(const RunnerSetup& setup, can::CanSocket socket, lcm::LCM& lcm, std::FILE* log, int control_fd)
      : setup_(setup),
        socket_(std::move(socket)),
        lcm_(lcm),
        log_(log),
        control_fd_(control_fd),
        sim_(setup.simulation, *setup.options.initial_q),
        schedule_(withDuration(setup.options)),
        clock_(1.0 / setup.options.state_rate_hz, kFreezeTolerance_s),
        joint_count_(setup.simulation.plant.jointCount()),
        streams_(setup.joint_devices) {
    switches_.heartbeat = setup.options.heartbeat;
  }

  int run();

 private:
  static std::vector<FaultEvent> withDuration(const SimOptions& options) {
    std::vector<FaultEvent> events = options.faults;
    if (options.duration_s > 0.0) {
      events.push_back(FaultEvent{FaultKind::kExit, 0, options.duration_s});
    }
    return events;
  }

  double now() const { return monotonicSeconds() - start_mono_s_; }
  // The simulation's time: now() without the time the process stood still (freeze_clock.hpp).
  double simNow() const { return clock_.simulationTime(now()); }
  void say(const char* format, ...) const __attribute__((format(printf, 2, 3)));
  // The same, for an event that happened at real time event_s (since start-up), not now.
  void sayAt(double event_s, const char* format, ...) const __attribute__((format(printf, 3, 4)));
  void vsay(double event_s, const char* format, va_list args) const;
  // A setpoint with a non-zero velocity arrived within the last 20 ms.
  bool movingNow() const { return last_moving_frame_s_ >= 0.0 && now() - last_moving_frame_s_ <= 0.020; }

  void onCanReadable();
  void onFrame(const can::Frame& frame, double real_s);
  void onHeartbeatTimer();
  void onStateTimer();
  void onFaultTimer();
  void onControlReadable();
  void applyFaultNow(FaultKind kind, const char* source);
  void armFaultTimer();
  void writeFrame(const can::Frame& frame, const char* what);
  // utime_us: the published ARM_STATE's own utime, or 0 to take the clock now.
  void writeLogRow(double t_s, bool published, std::int64_t utime_us = 0);
  void printSummary() const;

  const RunnerSetup& setup_;
  can::CanSocket socket_;
  lcm::LCM& lcm_;
  std::FILE* log_;
  int control_fd_;
  PlantSimulation sim_;
  FaultSchedule schedule_;
  FreezeClock clock_;
  ControlLines control_lines_;
  OutputSwitches switches_;
  RunCounters counters_;
  double start_mono_s_ = 0.0;
  posix::TimerFd heartbeat_timer_;
  posix::TimerFd state_timer_;
  posix::TimerFd fault_timer_;
  int joint_count_;  // N, from the plant
  JointStreams streams_;
  double last_moving_frame_s_ = -1.0;  // real time of the latest setpoint with a velocity
  bool link_trouble_ = false;          // a read or write failed since the last success: report once
};

void Runner::say(const char* format, ...) const {
  va_list args;
  va_start(args, format);
  vsay(now(), format, args);
  va_end(args);
}

void Runner::sayAt(double event_s, const char* format, ...) const {
  va_list args;
  va_start(args, format);
  vsay(event_s, format, args);
  va_end(args);
}

void Runner::vsay(double event_s, const char* format, va_list args) const {
  // Simulator time of the event, and the wall clock (what candump and LCM timestamps use) at
  // that moment.
  const std::int64_t wall_us = realtimeMicros() - static_cast<std::int64_t>(std::llround((now() - event_s) * 1e6));
  std::fprintf(stderr, "cyber-plant-sim: t=%.3f [%lld.%06lld] ", event_s, static_cast<long long>(wall_us / 1000000),
               static_cast<long long>(wall_us % 1000000));
  std::vfprintf(stderr, format, args);
  std::fputc('\n', stderr);
}

int Runner::run() {
  const posix::Epoll poll;
  const posix::SignalFd signals({SIGINT, SIGTERM});
  start_mono_s_ = monotonicSeconds();
  poll.add(socket_.fd(), kCanTag);
  poll.add(heartbeat_timer_.fd(), kHeartbeatTag);
  poll.add(state_timer_.fd(), kStateTag);
  poll.add(fault_timer_.fd(), kFaultTag);
  poll.add(signals.fd(), kSignalTag);
  if (control_fd_ >= 0) poll.add(control_fd_, kControlTag);
  // The first heartbeat and state go out at once, then on the period grid.
  heartbeat_timer_.startPeriodic(toNs(start_mono_s_), toNs(kHeartbeatPeriod_s));
  state_timer_.startPeriodic(toNs(start_mono_s_), toNs(1.0 / setup_.options.state_rate_hz));
  armFaultTimer();
  say("running on %s: %s, ARM_STATE on %s at %g Hz, heartbeat %s", setup_.can_interface.c_str(),
      devicesText(setup_.joint_devices).c_str(), setup_.state_channel.c_str(), setup_.options.state_rate_hz,
      switches_.heartbeat ? "on" : "off");

  while (!switches_.exit) {
    std::uint64_t tags[8];
    const int n = poll.wait(tags, 8);
    if (n < 0) {
      std::perror("cyber-plant-sim: epoll_wait");
      return 1;
    }
    clock_.onWake(now());
    for (int i = 0; i < n && !switches_.exit; ++i) {
      switch (tags[i]) {
        case kCanTag: onCanReadable(); break;
        case kHeartbeatTag: onHeartbeatTimer(); break;
        case kStateTag: onStateTimer(); break;
        case kFaultTag: onFaultTimer(); break;
        case kSignalTag:
          say("stopping on a signal");
          switches_.exit = true;
          break;
        case kControlTag: onControlReadable(); break;
        default: break;
      }
    }
  }
  const double end_s = now();
  sim_.advanceTo(clock_.simulationTime(end_s));
  writeLogRow(end_s, false);
  printSummary();
  return 0;
}

void Runner::onCanReadable() {
  can::Frame frame;
  // Drain what is queued; each frame is stamped when it is read.
  for (int budget = 0; budget < 256; ++budget) {
    const can::IoResult result = socket_.read(frame);
    if (result.status == can::IoStatus::kWouldBlock) return;
    if (!result.ok()) {
      ++counters_.read_failures;
      if (!link_trouble_) say("CAN read failed: %s", result.message().c_str());
      link_trouble_ = true;
      return;
    }
    onFrame(frame, now());
  }
}

void Runner::onFrame(const can::Frame& frame, double real_s) {
  const double t_s = clock_.simulationTime(real_s);
  if (frame.error) {
    ++counters_.bus_errors;
    return;
  }
  const auto decoded = can::decodeSetpoint(frame);
  if (!decoded) {
    const auto id = can::unpackFrcId(frame.id);
    const bool ours = frame.extended && id.device_type == can::kDeviceTypeMiscellaneous &&
                      id.manufacturer == can::kManufacturerTeamUse && id.api_class == can::kSetpointApiClass &&
                      id.api_index == can::kSetpointApiIndex;
    ++(ours ? counters_.malformed : counters_.other_frames);
    return;
  }
  const std::uint8_t device = decoded.value().device;
  const std::optional<int> joint = streams_.jointOf(device);
  if (!joint) {
    ++counters_.other_frames;
    return;
  }
  const can::Setpoint& sp = decoded.value().setpoint;
  // One velocity count (1e-3 unit/s) or more is motion; the streams are at rest again once the
  // latest frames of every joint carry zero velocity.
  const bool moving = std::abs(sp.velocity) >= 0.5 / can::kVelocityCountsPerUnit;
  const JointStreams::Update update = streams_.onSetpoint(*joint, sp.sequence, moving);
  if (update.first) say("first setpoint for device %u", device);
  // t_s is simulation time; the fault schedule runs on real time.
  sim_.receiveSetpoint(*joint, JointCommand{sp.position, sp.velocity, sp.feedforward_volts}, t_s);
  if (moving) last_moving_frame_s_ = real_s;
  if (update.motion_started) {
    schedule_.motionStarted(streams_.motions(), real_s);
    sayAt(real_s, "motion %d started (device %u)", streams_.motions(), device);
    armFaultTimer();
  } else if (update.came_to_rest) {
    say("at rest");
  }
}

void Runner::writeFrame(const can::Frame& frame, const char* what) {
  const can::IoResult result = socket_.write(frame);
  if (result.ok()) {
    if (link_trouble_) say("CAN works again (%s written)", what);
    link_trouble_ = false;
    return;
  }
  ++counters_.write_failures;
  if (!link_trouble_) say("CAN write of %s failed: %s", what, result.message().c_str());
  link_trouble_ = true;
}

void Runner::onHeartbeatTimer() {
  if (heartbeat_timer_.consume() == 0 || !switches_.heartbeat) return;
  can::Heartbeat heartbeat;
  heartbeat.enabled = switches_.heartbeat_enabled;
  heartbeat.system_watchdog = switches_.heartbeat_enabled;
  writeFrame(can::encodeHeartbeat(heartbeat), "heartbeat");
  ++counters_.heartbeats_sent;
}

void Runner::onStateTimer() {
  if (state_timer_.consume() == 0) return;
  const double t_s = now();
  sim_.advanceTo(clock_.simulationTime(t_s));
  bool published = false;
  std::int64_t published_utime = 0;
  if (switches_.publish_state) {
    cyberplanner::arm_state_t msg{};
    msg.utime = realtimeMicros();
    published_utime = msg.utime;
    // One value per joint of the description the simulator models (docs/lcm.md, "Joints by index").
    msg.num_joints = static_cast<std::int8_t>(joint_count_);
    for (int j = 0; j < joint_count_; ++j) {
      msg.position.push_back(sim_.state(j).position);
      msg.velocity.push_back(sim_.state(j).velocity);
    }
    msg.pieces = setup_.options.pieces;
    msg.num_pieces = static_cast<std::int8_t>(msg.pieces.size());
    if (lcm_.publish(setup_.state_channel, &msg) == 0) {
      ++counters_.states_published;
      published = true;
    } else if (counters_.publish_failures++ == 0) {
      say("LCM publish of %s failed", setup_.state_channel.c_str());
    }
  }
  writeLogRow(t_s, published, published ? published_utime : 0);
}

void Runner::onFaultTimer() {
  fault_timer_.consume();
  for (const FaultKind kind : schedule_.takeDue(now())) applyFaultNow(kind, "scheduled");
  armFaultTimer();
}

void Runner::applyFaultNow(FaultKind kind, const char* source) {
  say("fault %.*s (%s)", static_cast<int>(toString(kind).size()), toString(kind).data(), source);
  switches_ = applyFault(switches_, kind);
  if (kind == FaultKind::kBroadcastDisable) {
    writeFrame(can::makeBroadcastDisable(), "broadcast disable");
    ++counters_.disables_sent;
    // The controllers see the disable too: neutral until their next setpoint.
    sim_.advanceTo(simNow());
    sim_.disableOutputs();
  }
}

void Runner::onControlReadable() {
  char buffer[512];
  for (int budget = 0; budget < 64; ++budget) {
    const ssize_t got = ::read(control_fd_, buffer, sizeof buffer);
    if (got <= 0) return;  // EAGAIN: drained (the FIFO is open read-write, so never EOF)
    for (const ControlCommand& command : control_lines_.feed(std::string_view(buffer, static_cast<std::size_t>(got)))) {
      if (command.probe) {
        say("probe: %s", movingNow() ? "moving" : "not moving");
      } else if (!command.kind) {
        say("control: unknown command '%s' ignored", command.line.c_str());
      } else if (command.if_moving && !movingNow()) {
        say("control: %s skipped: not moving", command.line.c_str());
      } else {
        applyFaultNow(*command.kind, "control");
      }
    }
  }
}

void Runner::armFaultTimer() {
  const auto due = schedule_.nextDue_s();
  if (due) {
    fault_timer_.startOnce(toNs(start_mono_s_ + *due));
  } else {
    fault_timer_.stop();
  }
}

void Runner::writeLogRow(double t_s, bool published, std::int64_t utime_us) {
  if (log_ == nullptr) return;
  StateLogRow row;
  row.t_s = t_s;
  // A published row carries the message's utime, so the log tells exactly when each ARM_STATE
  // went out, even where a recorder missed it.
  row.utime = utime_us != 0 ? utime_us : realtimeMicros();
  row.joint_count = joint_count_;
  for (int joint = 0; joint < joint_count_; ++joint) {
    const auto j = static_cast<std::size_t>(joint);
    row.state[j] = sim_.state(joint);
    row.command[j] = sim_.effectiveCommand(joint, sim_.time_s());
    row.applied_volts[j] = sim_.appliedVolts(joint);
  }
  row.heartbeat = switches_.heartbeat;
  row.robot_enabled = switches_.heartbeat && switches_.heartbeat_enabled;
  row.state_published = published;
  const std::string line = stateLogRow(row);
  std::fputs(line.c_str(), log_);
  std::fputc('\n', log_);
}

void Runner::printSummary() const {
  const std::string positions = positionsText(setup_.joint_names, setup_.joint_units, sim_.positions());
  const std::string setpoints = setpointCountsText(setup_.joint_names, streams_);
  say("stopped: %s; setpoints %s, sequence gaps %ld, "
      "malformed %ld, other %ld, bus errors %ld, read failures %ld; sent heartbeats %ld, disables %ld, "
      "write failures %ld; ARM_STATE published %ld, failed %ld; motions %d; frozen %d times, %.3f s",
      positions.c_str(), setpoints.c_str(), streams_.sequenceGaps(), counters_.malformed, counters_.other_frames,
      counters_.bus_errors, counters_.read_failures, counters_.heartbeats_sent, counters_.disables_sent,
      counters_.write_failures, counters_.states_published, counters_.publish_failures, streams_.motions(),
      clock_.freezes(), clock_.frozenSeconds());
}

}  // namespace

int runSimulator(const RunnerSetup& setup, can::CanSocket socket, lcm::LCM& lcm, std::FILE* log, int control_fd) {
  // The descriptors are made at start-up and throw only then (cyber/posix/fd.hpp).
  try {
    Runner runner(setup, std::move(socket), lcm, log, control_fd);
    return runner.run();
  } catch (const std::system_error& error) {
    std::fprintf(stderr, "cyber-plant-sim: cannot set up the event loop: %s\n", error.what());
    return 1;
  }
}

}  // namespace cyber::plant

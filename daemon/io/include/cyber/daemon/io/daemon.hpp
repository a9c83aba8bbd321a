#pragma once
// cyber-plannerd assembled: the event loop (LCM, CAN, signals, timers) on the calling thread, the
// planning worker and the setpoint streamer on their own threads, the goal coordinator in between.

#include <lcm/lcm-cpp.hpp>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "cyber/can/can_socket.hpp"
#include "cyber/config/daemon_settings.hpp"
#include "cyber/daemon/frame_writer.hpp"
#include "cyber/daemon/goal_coordinator.hpp"
#include "cyber/daemon/io/event_loop.hpp"
#include "cyber/daemon/io/fd.hpp"
#include "cyber/daemon/io/lcm_bridge.hpp"
#include "cyber/daemon/io/log_throttle.hpp"
#include "cyber/daemon/io/planning_worker.hpp"
#include "cyber/daemon/io/streamer_thread.hpp"
#include "cyber/daemon/latency_histogram.hpp"
#include "cyber/daemon/robot_link.hpp"
#include "cyber/daemon/streamer.hpp"
#include "cyber/planner/robot_model.hpp"

namespace cyber::daemon::io {

// A start-up failure: what() is the one line to print before exiting non-zero.
class StartupError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct DaemonOptions {
  config::DaemonSettings settings;
  bool simulate_can = false;  // --can none: no socket, frames discarded, robot-enabled gate open
};

struct DaemonCounters {
  std::int64_t lcm_decode_errors = 0;   // undecodable or foreign messages on ARM_GOAL / ARM_STATE
  std::int64_t bad_states = 0;          // decodable ARM_STATE with non-finite or absurd values
  std::int64_t can_decode_errors = 0;   // heartbeat-id frames with a bad payload
  std::int64_t can_read_errors = 0;
  std::int64_t bus_errors = 0;          // error frames from the controller
  std::int64_t broadcast_disables = 0;
};

class Daemon final : private CoordinatorSink {
 public:
  // Opens LCM and (unless simulating) the CAN interface; throws StartupError with one line.
  // `signals` (may be null) is the SIGTERM/SIGINT descriptor main() created before any thread.
  Daemon(const planner::RobotModel& robot, const DaemonOptions& options, const PlanningService& planning,
         const SignalFd* signals);
  ~Daemon() override;
  Daemon(const Daemon&) = delete;
  Daemon& operator=(const Daemon&) = delete;

  // Runs until SIGTERM/SIGINT or requestStop(): holds, cancels open goals, exits. Returns 0.
  int run();
  // Thread-safe: the same clean stop as a signal.
  void requestStop();
  // Thread-safe: runs `task` on the loop thread.
  void post(EventLoop::Handler task) { loop_.post(std::move(task)); }
  // Loop thread: a goal as if it had arrived on ARM_GOAL.
  void handleGoal(const GoalRequest& goal);

  // Loop thread only: the daemon's LCM instance (tests on memq:// publish and subscribe through it).
  lcm::LCM& lcm() { return *lcm_; }
  // For benchmarks: goal received -> first setpoint of its plan streamed, and the streamer.
  [[nodiscard]] const LatencyHistogram& goalToSetpointLatency() const { return goal_latency_; }
  [[nodiscard]] StreamerChannels& channels() { return channels_; }
  void setTickObserver(TickObserver observer, void* context) { streamer_thread_.setObserver(observer, context); }

 private:
  // CoordinatorSink
  void publishStatus(const StatusUpdate& update) override;
  void publishTrajectory(std::int64_t request_id, const SharedSetpointSource& trajectory, MonoNs start_ns) override;
  void startPlanning(const PlanJob& job) override;
  void postProgram(std::unique_ptr<Program> program) override;
  void note(NoteLevel level, const std::string& text) override;

  void onGoalMessage(const cyberplanner::arm_goal_t& message);
  void onStateMessage(const cyberplanner::arm_state_t& message);
  void onUndecodable(const std::string& channel, int size);
  void onCanReadable();
  void onPlanDone();
  void onStreamerWake();
  void onStatusTimer();
  void onEchoTimer();
  void publishSetpointEcho();  // the latest tick on ARM_SETPOINT, once per tick
  void onSignal();
  void beginShutdown(const char* why);
  void publishDaemonStatus(MonoNs now);
  void flushTrajectory(MonoNs now, bool force);
  void storeInputs() { channels_.inputs.store(inputs_); }
  [[nodiscard]] bool robotEnabled(MonoNs now) const;
  [[nodiscard]] std::string serviceStatus() const;  // one line for systemd's STATUS=

  planner::RobotModel robot_;
  DaemonOptions options_;
  GateSettings gate_;
  const SignalFd* signals_;

  std::unique_ptr<lcm::LCM> lcm_;
  std::optional<can::CanSocket> can_;
  std::unique_ptr<CanPort> port_;
  // The streamer's own receive-only socket for the frames that gate motion (robot_link.hpp).
  std::optional<can::CanSocket> robot_can_;
  std::unique_ptr<RobotFrameSource> robot_source_;

  StreamerChannels channels_;
  Streamer streamer_;
  FrameWriter writer_;
  StreamerThread streamer_thread_;
  PlanningWorker worker_;
  GoalCoordinator coordinator_;
  EventLoop loop_;
  std::unique_ptr<LcmBridge> bridge_;
  TimerFd status_timer_;
  TimerFd echo_timer_;
  TimerFd exit_timer_;

  RobotInputsData inputs_;
  DaemonCounters counters_;
  LatencyHistogram plan_times_;
  LatencyHistogram goal_latency_;
  std::unordered_map<std::int64_t, MonoNs> goal_received_ns_;
  std::int64_t last_echo_tick_ = 0;
  // ARM_TRAJECTORY is rate-limited (a flood of goals would otherwise put ~200 messages of up to
  // 56 kB per second on the network): a plan adopted too soon after the last one published waits,
  // and is replaced by a newer one, which supersedes it.
  struct PendingTrajectory {
    std::int64_t request_id = 0;
    SharedSetpointSource trajectory;
    MonoNs start_ns = 0;
  };
  std::optional<PendingTrajectory> pending_trajectory_;
  MonoNs last_trajectory_ns_ = kNever;
  MonoNs last_service_status_ns_ = kNever;
  bool last_goal_failed_ = false;
  MonoNs bus_error_ns_ = kNever;
  MonoNs can_suspended_until_ = kNever;
  bool shutting_down_ = false;

  LogThrottle decode_log_, state_log_, can_log_, reject_log_, disable_log_;
};

}  // namespace cyber::daemon::io

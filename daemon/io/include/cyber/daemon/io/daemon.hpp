#pragma once
// cyber-plannerd assembled (docs/design.md, "Threads and ownership"): the event loop on the
// calling thread, the planning worker and the setpoint streamer on their own threads, and the
// parts of the loop, each with one job: LcmInput (goals and states in), CanInput (controller
// errors), GoalHandler (the goal coordinator and its outputs), StatusPublisher (what the daemon
// says about itself). The Daemon wires them, starts and stops the threads, and hands the
// streamer's events to the goal handler.

#include <lcm/lcm-cpp.hpp>

#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "cyber/can/can_socket.hpp"
#include "cyber/config/daemon_settings.hpp"
#include "cyber/config/load_config.hpp"
#include "cyber/daemon/frame_writer.hpp"
#include "cyber/daemon/io/can_input.hpp"
#include "cyber/daemon/io/event_loop.hpp"
#include "cyber/daemon/io/fd.hpp"
#include "cyber/daemon/io/goal_handler.hpp"
#include "cyber/daemon/io/lcm_bridge.hpp"
#include "cyber/daemon/io/lcm_input.hpp"
#include "cyber/daemon/io/planning_worker.hpp"
#include "cyber/daemon/io/state_receiver.hpp"
#include "cyber/daemon/io/status_publisher.hpp"
#include "cyber/daemon/io/streamer_thread.hpp"
#include "cyber/daemon/robot_link.hpp"
#include "cyber/daemon/streamer.hpp"
#include "cyber/planner.hpp"

namespace cyber::daemon::io {

// A start-up failure: what() is the one line to print before exiting non-zero.
class StartupError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct DaemonOptions {
  config::DaemonSettings settings;
  bool simulate_can = false;           // --can none: no socket, frames discarded, robot-enabled gate open
  std::vector<config::PoseSet> poses;  // the configuration's named poses, for ARM_GOAL's pose_name
};

class Daemon final {
 public:
  // Opens LCM and (unless simulating) the CAN interface; throws StartupError with one line.
  // `signals` (may be null) is the SIGTERM/SIGINT descriptor main() created before any thread.
  Daemon(const planner::RobotModel& robot, const DaemonOptions& options, const PlanningService& planning,
         const SignalFd* signals);
  ~Daemon();
  Daemon(const Daemon&) = delete;
  Daemon& operator=(const Daemon&) = delete;

  // Runs until SIGTERM/SIGINT or requestStop(): holds, cancels open goals, exits. Returns 0.
  int run();
  // Thread-safe: the same clean stop as a signal.
  void requestStop();

 private:
  friend class DaemonProbe;  // tests and benchmarks (daemon_probe.hpp)

  void onGoal(const GoalRequest& goal);
  void onStreamerWake();
  void onStatusTimer();
  void onSignal();
  void beginShutdown(const char* why);

  planner::RobotModel robot_;
  DaemonOptions options_;
  GateSettings gate_;
  const SignalFd* signals_;

  std::unique_ptr<lcm::LCM> lcm_;
  std::unique_ptr<lcm::LCM> state_lcm_;  // ARM_STATE alone, on the state receiver's thread
  std::optional<can::CanSocket> can_;
  std::unique_ptr<CanPort> port_;
  // The streamer's receive-only socket for the frames that gate motion (robot_link.hpp).
  std::optional<can::CanSocket> robot_can_;
  std::unique_ptr<RobotFrameSource> robot_source_;

  StreamerChannels channels_;
  Streamer streamer_;
  FrameWriter writer_;
  StreamerThread streamer_thread_;
  PlanningWorker worker_;
  EventLoop loop_;
  LcmInput lcm_input_;
  LcmBridge bridge_;
  StateReceiver state_receiver_;
  GoalHandler goals_;
  std::unique_ptr<CanInput> can_input_;  // null without a CAN bus
  StatusPublisher status_;
  TimerFd status_timer_;
  TimerFd echo_timer_;
  TimerFd exit_timer_;
  bool shutting_down_ = false;
};

}  // namespace cyber::daemon::io

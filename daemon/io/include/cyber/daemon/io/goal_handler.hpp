#pragma once
// The goals' side of the event loop: the GoalCoordinator and what it asks for (ARM_PLAN_STATUS
// with its log lines, ARM_TRAJECTORY, plans on the worker, programs for the streamer), fed with
// the plan results and the streamer's events; and the plan times and goal-to-first-setpoint
// latency they show.

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>

#include "cyber/daemon/goal_coordinator.hpp"
#include "cyber/daemon/io/event_loop.hpp"
#include "cyber/daemon/io/latency_histogram.hpp"
#include "cyber/daemon/io/lcm_bridge.hpp"
#include "cyber/daemon/io/log_throttle.hpp"
#include "cyber/daemon/io/planning_worker.hpp"
#include "cyber/daemon/io/streamer_thread.hpp"
#include "cyber/daemon/io/trajectory_publisher.hpp"

namespace cyber::daemon::io {

class GoalHandler final : private CoordinatorSink {
 public:
  struct Settings {
    CoordinatorSettings coordinator;
    double trajectory_step_s = 0.01;
  };

  // Everything referenced must outlive this; all calls on the event-loop thread.
  GoalHandler(const planner::RobotModel& robot, const Settings& settings, LcmBridge& bridge, PlanningWorker& worker,
              StreamerChannels& channels, EventLoop& loop);

  // A goal received at `now`; `gate` is the motion gate at that time.
  void onGoal(const GoalRequest& goal, MonoNs now, GateVerdict gate);
  // The worker's wake descriptor is readable.
  void onPlanDone();
  void onStreamEvent(const StreamEvent& event, MonoNs now);
  // Periodic: retries waiting goals, publishes a waiting trajectory.
  void onTimer(MonoNs now);
  // Every open goal is cancelled and later goals are rejected.
  void onShutdown(MonoNs now) { coordinator_.onShutdown(now); }
  // ARM_CANCEL received at `now`.
  void onCancel(const CancelRequest& cancel, MonoNs now);

  [[nodiscard]] const CoordinatorCounters& counters() const { return coordinator_.counters(); }
  // The latest final answer was REJECTED or FAILED (CAN status fault bit "plan failed").
  [[nodiscard]] bool lastGoalFailed() const { return last_goal_failed_; }
  [[nodiscard]] const LatencyHistogram& planTimes() const { return plan_times_; }
  // Goal received -> first setpoint of its plan streamed.
  [[nodiscard]] const LatencyHistogram& goalLatency() const { return goal_latency_; }

 private:
  // CoordinatorSink
  void publishStatus(const StatusUpdate& update) override;
  void publishTrajectory(std::int64_t request_id, const SharedSetpointSource& trajectory, MonoNs start_ns) override;
  void startPlanning(const PlanJob& job) override;
  void postProgram(std::unique_ptr<Program> program) override;
  void note(NoteLevel level, const std::string& text) override;
  void setReleaseGeneration(std::uint32_t generation) override;

  const planner::RobotModel& robot_;  // joint names for the log
  LcmBridge& bridge_;
  PlanningWorker& worker_;
  StreamerChannels& channels_;
  EventLoop& loop_;
  TrajectoryPublisher trajectories_;
  GoalCoordinator coordinator_;
  LatencyHistogram plan_times_;
  LatencyHistogram goal_latency_;
  std::unordered_map<std::int64_t, MonoNs> goal_received_ns_;
  bool last_goal_failed_ = false;
  ThrottledWarning reject_warning_;
};

}  // namespace cyber::daemon::io

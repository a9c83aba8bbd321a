#pragma once
// The life of every goal, on the event-loop thread: validation, latest-wins coalescing of the goals
// waiting for the planner (the plan in progress still runs; the newest goal is spliced into it), choosing
// where a plan starts (at rest, or the commanded state a measured budget ahead of a running
// motion), splicing finished plans into the streamer's program, and answering on ARM_PLAN_STATUS.
// Single-threaded and clock-free: the caller passes "now", the plan results and the streamer's
// events, and receives its decisions through CoordinatorSink.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cyber/daemon/goal_request.hpp"
#include "cyber/daemon/goal_status.hpp"
#include "cyber/daemon/mono_time.hpp"
#include "cyber/daemon/motion_gate.hpp"
#include "cyber/daemon/planning_budget.hpp"
#include "cyber/daemon/planning_service.hpp"
#include "cyber/daemon/program.hpp"
#include "cyber/daemon/stream_event.hpp"
#include "cyber/planner/robot_model.hpp"

namespace cyber::daemon {

struct PlanJob {
  std::uint64_t job_id = 0;
  std::int64_t request_id = 0;
  MotionRequest request;
};

enum class NoteLevel { kDebug, kInfo, kWarn };

class CoordinatorSink {
 public:
  virtual ~CoordinatorSink() = default;
  virtual void publishStatus(const StatusUpdate& update) = 0;
  // Once the streamer has adopted the plan: sample 0 is commanded at start_ns.
  virtual void publishTrajectory(std::int64_t request_id, const SharedSetpointSource& trajectory, MonoNs start_ns) = 0;
  // Hand a job to the planning worker; its result comes back through onPlanResult.
  virtual void startPlanning(const PlanJob& job) = 0;
  // Hand a program to the streamer; it answers with an adopted or rejected event.
  virtual void postProgram(std::unique_ptr<Program> program) = 0;
  // A decision worth a log line (late plans, fall-backs).
  virtual void note(NoteLevel level, const std::string& text) = 0;
};

struct CoordinatorSettings {
  double planning_budget_s = 0.03;  // configured minimum
  double stream_period_s = 0.005;
  double max_budget_s = 1.0;
  int max_late_attempts = 3;        // then finish the running motion and plan from rest
};

struct CoordinatorCounters {
  std::int64_t goals_received = 0;
  std::int64_t goals_rejected = 0;   // REJECTED answers
  std::int64_t plans_succeeded = 0;
  std::int64_t plans_failed = 0;     // FAILED answers
  std::int64_t plans_late = 0;       // plans that missed their splice time
  std::int64_t goals_done = 0;
};

class GoalCoordinator {
 public:
  GoalCoordinator(const planner::RobotModel& robot, const CoordinatorSettings& settings, CoordinatorSink& sink);

  // A goal from ARM_GOAL; `gate` is the motion gate at `now` as the event loop evaluates it.
  void onGoal(const GoalRequest& goal, MonoNs now, GateVerdict gate);
  // The worker finished job_id after plan_time_s of wall time.
  void onPlanResult(std::uint64_t job_id, planner::Result<PlannedMotion> result, double plan_time_s, MonoNs now);
  void onStreamEvent(const StreamEvent& event, MonoNs now);
  // Periodic retry of a goal that waits for room in the program chain.
  void onTimer(MonoNs now);
  // Shutdown: every open goal is cancelled and later goals are rejected.
  void onShutdown(MonoNs now);

  [[nodiscard]] const CoordinatorCounters& counters() const { return counters_; }
  [[nodiscard]] double budgetS() const { return budget_.budgetS(); }
  [[nodiscard]] bool idle() const { return !pending_ && !in_flight_ && !posted_; }
  // The program the streamer runs, as far as the coordinator knows (for tests and status).
  [[nodiscard]] const Program& mirror() const { return mirror_; }

 private:
  struct Pending {
    ValidGoal goal;
    int attempt = 0;
    bool from_rest = false;  // fall-back: start where the running motion ends
  };
  struct InFlight {
    std::uint64_t job_id = 0;
    Pending pending;
    std::uint64_t base_id = 0;
    std::uint64_t base_epoch = 0;
    MonoNs branch_ns = 0;
    bool floating = false;
  };
  struct Posted {
    std::uint64_t program_id = 0;
    Program program;
    Pending pending;
    std::vector<std::int64_t> dropped;
  };
  struct OpenGoal {
    StageTimesMs times_ms;
    double duration_s = 0.0;
    bool executing = false;
  };

  void tryStart(MonoNs now);
  void replan(const Pending& pending, bool late, MonoNs now, const std::string& why);
  void publish(std::int64_t request_id, GoalStatus status, std::string reason = {});
  void finish(std::int64_t request_id, GoalStatus status, std::string reason);
  void reject(std::int64_t request_id, std::string reason);
  void cancelScheduled(const std::string& reason);

  planner::RobotModel robot_;
  CoordinatorSettings settings_;
  CoordinatorSink& sink_;
  PlanningBudget budget_;
  CoordinatorCounters counters_;

  Program mirror_;
  bool stopped_ = true;  // the streamer streams nothing (no state, disabled)
  bool shut_down_ = false;
  std::string stop_reason_ = "no ARM_STATE received yet";

  std::optional<Pending> pending_;
  std::optional<InFlight> in_flight_;
  std::optional<Posted> posted_;
  std::map<std::int64_t, OpenGoal> open_;          // accepted, no final status yet
  std::optional<std::int64_t> executing_;          // request being streamed
  std::uint64_t next_job_id_ = 1;
  std::uint64_t next_program_id_ = 1;
};

}  // namespace cyber::daemon

#pragma once
// The life of every goal, on the event-loop thread: validation, latest-wins coalescing of the goals
// waiting for the planner (the plan in progress still runs; the newest goal is spliced into it), choosing
// where a plan starts (at rest, or the commanded state a measured budget ahead of a running
// motion), splicing finished plans into the streamer's program, and answering on ARM_PLAN_STATUS.
// Single-threaded and clock-free: the caller passes "now", the plan results and the streamer's
// events, and receives its decisions through CoordinatorSink. Its state machine, two regions
// (the stream as the streamer reports it, the goal in the planning pipeline), is drawn in
// docs/design.md, "The life of a goal".

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
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
  int max_late_attempts = 3;  // then finish the running motion and plan from rest
};

struct CoordinatorCounters {
  std::int64_t goals_received = 0;
  std::int64_t goals_rejected = 0;  // REJECTED answers
  std::int64_t plans_succeeded = 0;
  std::int64_t plans_failed = 0;  // FAILED answers
  std::int64_t plans_late = 0;    // plans that missed their splice time
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
  [[nodiscard]] bool idle() const { return !waiting_ && std::holds_alternative<Idle>(stage_); }
  // The program the streamer runs, as far as the coordinator knows (for tests and status).
  [[nodiscard]] const Program& mirror() const { return mirror_; }

 private:
  // A goal on its way to the streamer and what a re-plan carries over.
  struct Attempt {
    ValidGoal goal;
    int attempt = 0;         // plans of this goal so far
    bool from_rest = false;  // fall-back: start where the running motion ends
  };

  // The stream region: what the streamer does, as its events report it.
  struct Stopped {  // streams nothing (no state, gate closed): nothing is planned
    std::string reason;
  };
  struct Streaming {};  // holding or moving: plans may start
  struct ShutDown {};   // terminal: goals are rejected, nothing is planned or posted
  using StreamState = std::variant<Stopped, Streaming, ShutDown>;

  // The pipeline region: at most one goal is at the worker or at the streamer.
  struct Idle {};
  struct Planning {  // a PlanJob at the worker; left on its result
    std::uint64_t job_id = 0;
    Attempt attempt;
    std::uint64_t base_id = 0;  // the program and epoch the plan splices into
    std::uint64_t base_epoch = 0;
    MonoNs branch_ns = 0;
    bool floating = false;  // starts at rest, when adopted: no splice deadline
  };
  struct Posted {  // a program at the streamer; left on its kAdopted or kRejected
    std::uint64_t program_id = 0;
    Program program;
    Attempt attempt;
    std::vector<std::int64_t> dropped;                          // requests whose segments the program replaced
    std::vector<std::pair<std::int64_t, std::int64_t>> pruned;  // segments over (request, superseded by)
  };
  using Stage = std::variant<Idle, Planning, Posted>;

  struct OpenGoal {  // accepted, no final status yet
    StageTimesMs times_ms;
    double duration_s = 0.0;
  };

  // Transitions of the pipeline (each called only from the state it names).
  void startPlanning(MonoNs now);  // Idle -> Planning, when a goal waits and the stream runs
  void onPlanned(Planning job, planner::Result<PlannedMotion> result, double plan_time_s,
                 MonoNs now);                                            // Planning -> Posted | Idle
  void onAdopted(Posted posted, const StreamEvent& event, MonoNs now);   // Posted -> Idle
  void onRejected(Posted posted, const StreamEvent& event, MonoNs now);  // Posted -> Idle
  void replan(const Attempt& attempt, bool late, MonoNs now, const std::string& why);

  // Transitions of the stream region.
  void onStopped(const StreamEvent& event);
  void onHolding(const StreamEvent& event, MonoNs now);

  // The goals streamed and finished, as the streamer reports them.
  void onExecuting(const StreamEvent& event, MonoNs now);

  [[nodiscard]] bool shutDown() const { return std::holds_alternative<ShutDown>(stream_); }
  [[nodiscard]] const std::string* stopReason() const;  // nullptr unless Stopped
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
  StreamState stream_ = Stopped{"no ARM_STATE received yet"};
  Stage stage_ = Idle{};
  std::optional<Attempt> waiting_;  // latest wins: the next goal for the worker
  std::map<std::int64_t, OpenGoal> open_;
  std::optional<std::int64_t> executing_;  // the open request being streamed
  std::uint64_t next_job_id_ = 1;
  std::uint64_t next_program_id_ = 1;
};

}  // namespace cyber::daemon

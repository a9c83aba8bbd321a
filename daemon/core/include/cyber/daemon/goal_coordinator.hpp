#pragma once
// The life of every goal, on the event-loop thread: validation, latest-wins coalescing of the goals
// waiting for the planner (the plan in progress still runs; the newest goal is spliced into it), choosing
// where a plan starts (at rest, or the commanded state a measured budget ahead of a running
// motion), splicing finished plans into the streamer's program, answering on ARM_PLAN_STATUS, and
// ARM_CANCEL: a hold (brake to rest, planned like a moving start) or a release (manual override:
// the streamer stops until the next goal). Single-threaded and clock-free: the caller passes "now", the plan results
// and the streamer's events, and receives its decisions through CoordinatorSink. Its state machine, two regions (the
// stream as the streamer reports it, the goal in the planning pipeline), is drawn in docs/design.md, "The life of a
// goal".

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "cyber/daemon/cancel_request.hpp"
#include "cyber/daemon/goal_request.hpp"
#include "cyber/daemon/goal_status.hpp"
#include "cyber/daemon/mono_time.hpp"
#include "cyber/daemon/motion_gate.hpp"
#include "cyber/daemon/planning_budget.hpp"
#include "cyber/daemon/planning_service.hpp"
#include "cyber/daemon/program.hpp"
#include "cyber/daemon/stream_event.hpp"
#include "cyber/planner.hpp"

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
  // The manual override for the streamer (RobotInputs::release_generation): odd while released.
  virtual void setReleaseGeneration(std::uint32_t generation) = 0;
};

struct CoordinatorSettings {
  double planning_budget_s = 0.03;  // configured minimum
  double stream_period_s = 0.005;
  double max_budget_s = 1.0;
  int max_late_attempts = 3;  // then finish the running motion and plan from rest
  PoseLookup poses;           // resolves ARM_GOAL's pose_name (the configuration's named poses)
};

struct CoordinatorCounters {
  std::int64_t goals_received = 0;
  std::int64_t goals_rejected = 0;  // REJECTED answers
  std::int64_t plans_succeeded = 0;
  std::int64_t plans_failed = 0;  // FAILED answers
  std::int64_t plans_late = 0;    // plans that missed their splice time
  std::int64_t goals_done = 0;
  std::int64_t goals_cancelled = 0;  // CANCELLED answers to ARM_CANCEL
  std::int64_t stops_planned = 0;    // ARM_CANCEL holds that braked a moving mechanism (stop posted)
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
  // ARM_CANCEL (docs/lcm.md, "Cancel and manual override"). A cancel that names no open goal
  // changes nothing: a stale cancel must not stop a newer move.
  void onCancel(const CancelRequest& cancel, MonoNs now);

  [[nodiscard]] const CoordinatorCounters& counters() const { return counters_; }
  [[nodiscard]] double budgetS() const { return budget_.budgetS(); }
  [[nodiscard]] bool idle() const { return !waiting_ && std::holds_alternative<Idle>(stage_); }
  // The program the streamer runs, as far as the coordinator knows (for tests and status).
  [[nodiscard]] const Program& mirror() const { return mirror_; }
  // The robot program drives the joints (ARM_CANCEL's release) until the next goal.
  [[nodiscard]] bool released() const { return std::holds_alternative<Released>(stream_); }

 private:
  // A goal on its way to the streamer and what a re-plan carries over.
  struct Attempt {
    ValidGoal goal;          // a stop: the request and world of the motion it brakes, set when planned
    int attempt = 0;         // plans of this goal so far
    bool from_rest = false;  // fall-back: start where the running motion ends (a stop: give up)
    bool stop = false;       // ARM_CANCEL's hold: the fastest stop of the running motion
    bool cancelled = false;  // ARM_CANCEL ended it at the worker or the streamer: never posted again
    // Why planning from the moving start failed, when this attempt starts where the motion ends.
    std::string moving_start_failure;
  };

  // The stream region: what the streamer does, as its events report it.
  struct Stopped {  // streams nothing (no state, gate closed): nothing is planned
    std::string reason;
  };
  struct Streaming {};  // holding or moving: plans may start
  struct Released {};   // ARM_CANCEL's release: the streamer sends nothing; the next goal ends it
  struct ShutDown {};   // terminal: goals are rejected, nothing is planned or posted
  using StreamState = std::variant<Stopped, Streaming, Released, ShutDown>;

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

  struct World {  // what a segment was planned among: a stop of it keeps the same clearance
    planner::HeldPieces pieces;
    int scene = 0;
    double scene_offset_m = 0.0;
  };

  // Transitions of the pipeline (each called only from the state it names).
  void startPlanning(MonoNs now);  // Idle -> Planning, when a goal waits and the stream runs
  void onPlanned(Planning job, planner::Result<PlannedMotion> result, double plan_time_s,
                 MonoNs now);                                            // Planning -> Posted | Idle
  void onAdopted(Posted posted, const StreamEvent& event, MonoNs now);   // Posted -> Idle
  void onRejected(Posted posted, const StreamEvent& event, MonoNs now);  // Posted -> Idle
  void replan(const Attempt& attempt, bool late, MonoNs now, const std::string& why);
  // A goal whose plan from the moving start failed: planned again from where the running motion
  // ends at rest (the motion is collision-free and ends inside the limits). False when the
  // failure is the goal's own, which no other start changes.
  bool retryFromRest(const Attempt& attempt, const planner::PlanError& error);
  // Fills a stop's request and world from the motion at the branch; false when there is nothing to
  // brake (at rest by then) or it must not be braked (no world known, given up after late plans).
  bool prepareStop(Attempt& stop, const ProgramSample& at_branch);

  // ARM_CANCEL.
  void cancelOpen(const std::string& reason);  // every open goal CANCELLED; plans in flight dropped
  void release();                              // Streaming | Stopped -> Released
  void endRelease();                           // Released -> Stopped, until the streamer holds again

  // Transitions of the stream region.
  void onStopped(const StreamEvent& event);
  void onHolding(const StreamEvent& event, MonoNs now);

  // The goals streamed and finished, as the streamer reports them.
  void onExecuting(const StreamEvent& event, MonoNs now);

  [[nodiscard]] bool shutDown() const { return std::holds_alternative<ShutDown>(stream_); }
  [[nodiscard]] std::optional<std::string_view> stopReason() const;  // nothing unless Stopped or Released
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
  std::map<std::int64_t, World> worlds_;   // of the mirror's segments, by request
  std::uint32_t release_generation_ = 0;   // RobotInputs::release_generation as last set
  std::uint64_t next_job_id_ = 1;
  std::uint64_t next_program_id_ = 1;
};

}  // namespace cyber::daemon

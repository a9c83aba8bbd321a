#include "cyber/daemon/goal_coordinator.hpp"

#include <fmt/format.h>

#include <utility>

namespace cyber::daemon {

namespace {

std::string superseded(std::int64_t by) { return "superseded by request " + std::to_string(by); }

std::string ms(double seconds) { return fmt::format("{:.1f} ms", seconds * 1e3); }

}  // namespace

GoalCoordinator::GoalCoordinator(const planner::RobotModel& robot, const CoordinatorSettings& settings,
                                 CoordinatorSink& sink)
    : robot_(robot),
      settings_(settings),
      sink_(sink),
      budget_(settings.planning_budget_s, settings.stream_period_s + 0.001, settings.max_budget_s) {}

void GoalCoordinator::publish(std::int64_t request_id, GoalStatus status, std::string reason) {
  StatusUpdate update;
  update.request_id = request_id;
  update.status = status;
  update.reason = std::move(reason);
  if (auto it = open_.find(request_id); it != open_.end()) {
    update.times_ms = it->second.times_ms;
    update.duration_s = it->second.duration_s;
  }
  sink_.publishStatus(update);
}

const std::string* GoalCoordinator::stopReason() const {
  const auto* stopped = std::get_if<Stopped>(&stream_);
  return stopped != nullptr ? &stopped->reason : nullptr;
}

// Publishes a final status once: a goal that already has one is left alone.
void GoalCoordinator::finish(std::int64_t request_id, GoalStatus status, std::string reason) {
  auto it = open_.find(request_id);
  if (it == open_.end()) return;
  publish(request_id, status, std::move(reason));
  open_.erase(it);
  if (executing_ == request_id) executing_.reset();
  switch (status) {
    case GoalStatus::kRejected: ++counters_.goals_rejected; break;
    case GoalStatus::kFailed: ++counters_.plans_failed; break;
    case GoalStatus::kDone: ++counters_.goals_done; break;
    default: break;
  }
}

// A goal refused on arrival: answered at once, without touching a goal of the same id in progress.
void GoalCoordinator::reject(std::int64_t request_id, std::string reason) {
  StatusUpdate update;
  update.request_id = request_id;
  update.status = GoalStatus::kRejected;
  update.reason = std::move(reason);
  sink_.publishStatus(update);
  ++counters_.goals_rejected;
}

void GoalCoordinator::onGoal(const GoalRequest& goal, MonoNs now, GateVerdict gate) {
  ++counters_.goals_received;
  auto valid = validateGoal(goal, robot_);
  if (!valid) {
    reject(goal.request_id, std::string(planner::toString(valid.error().status)) + ": " + valid.error().reason);
    return;
  }
  if (shutDown()) {
    reject(goal.request_id, "daemon shutting down");
    return;
  }
  if (!gate.open()) {
    reject(goal.request_id, "no motion allowed: " + std::string(toString(gate.reason)));
    return;
  }
  // A sender that reuses an id still open replaces that goal.
  if (open_.count(goal.request_id) != 0) finish(goal.request_id, GoalStatus::kCancelled, superseded(goal.request_id));
  open_[goal.request_id] = OpenGoal{};
  publish(goal.request_id, GoalStatus::kAccepted);

  // Latest wins among the goals waiting for the worker. The plan being computed is not thrown
  // away: it runs when ready and the newest goal is spliced into it, so a steady stream of goals
  // faster than the planner still moves the mechanism instead of starving it.
  if (waiting_) finish(waiting_->goal.request_id, GoalStatus::kCancelled, superseded(goal.request_id));
  waiting_ = Attempt{valid.value(), 0, false};
  startPlanning(now);
}

void GoalCoordinator::startPlanning(MonoNs now) {
  if (!waiting_ || !std::holds_alternative<Idle>(stage_) || !std::holds_alternative<Streaming>(stream_)) return;
  // A chain without room for one more segment ages out within a budget; onTimer retries.
  if (!Program::splice(mirror_, SpliceRequest{now, Segment{nullptr, -1, kNever}, true, 0})) return;

  Planning job;
  job.job_id = next_job_id_++;
  job.attempt = *waiting_;
  job.base_id = mirror_.id;
  job.base_epoch = mirror_.epoch;
  waiting_.reset();

  MotionRequest request;
  request.goal = job.attempt.goal.q;
  request.pieces = job.attempt.goal.pieces;
  request.scene = job.attempt.goal.scene;
  const MonoNs branch = now + secondsToNs(budget_.budgetS());
  const ProgramSample at_branch = mirror_.sample(branch, HoldModel(robot_));
  if (job.attempt.from_rest || !at_branch.moving) {
    // From rest: no deadline, the plan starts when it is ready (or when the motion ends).
    job.floating = true;
    request.start = mirror_.restPosition();
  } else {
    job.floating = false;
    job.branch_ns = branch;
    request.start = at_branch.setpoints.position;
    request.start_velocity = at_branch.setpoints.velocity;
  }
  if (job.attempt.attempt == 0) publish(job.attempt.goal.request_id, GoalStatus::kPlanning);
  const PlanJob plan_job{job.job_id, job.attempt.goal.request_id, request};
  stage_ = std::move(job);
  sink_.startPlanning(plan_job);
}

void GoalCoordinator::replan(const Attempt& attempt, bool late, MonoNs now, const std::string& why) {
  if (waiting_) {
    // A newer goal is already waiting: this one is superseded rather than re-planned.
    finish(attempt.goal.request_id, GoalStatus::kCancelled, superseded(waiting_->goal.request_id));
    return;
  }
  Attempt next = attempt;
  ++next.attempt;
  if (late && next.attempt >= settings_.max_late_attempts && !next.from_rest) {
    next.from_rest = true;
    sink_.note(NoteLevel::kWarn, "request " + std::to_string(attempt.goal.request_id) + ": " + why +
                                     "; finishing the running motion and planning from where it ends");
  } else {
    sink_.note(late ? NoteLevel::kWarn : NoteLevel::kInfo,
               "request " + std::to_string(attempt.goal.request_id) + ": " + why + "; re-planning from a later point");
  }
  waiting_ = next;
  startPlanning(now);
}

void GoalCoordinator::onPlanResult(std::uint64_t job_id, planner::Result<PlannedMotion> result, double plan_time_s,
                                   MonoNs now) {
  auto* planning = std::get_if<Planning>(&stage_);
  if (planning == nullptr || planning->job_id != job_id) return;  // not the job at the worker
  Planning job = std::move(*planning);
  stage_ = Idle{};
  budget_.record(plan_time_s);
  // After shutdown the goal has its final status and nothing more is posted.
  if (!shutDown()) onPlanned(std::move(job), std::move(result), plan_time_s, now);
}

void GoalCoordinator::onPlanned(Planning job, planner::Result<PlannedMotion> result, double plan_time_s, MonoNs now) {
  const std::int64_t id = job.attempt.goal.request_id;
  if (const std::string* reason = stopReason()) {
    finish(id, GoalStatus::kCancelled, "motion stopped while planning: " + *reason);
    return;
  }
  if (mirror_.id != job.base_id || mirror_.epoch != job.base_epoch) {
    replan(job.attempt, false, now, "the running motion changed while planning");
    return;
  }
  if (!result) {
    const planner::PlanError& error = result.error();
    finish(id, statusOfPlanError(error.status), std::string(planner::toString(error.status)) + ": " + error.reason);
    startPlanning(now);
    return;
  }
  PlannedMotion motion = std::move(result).value();
  if (!motion.trajectory) {
    finish(id, GoalStatus::kFailed, "internal error: the planner returned no trajectory");
    startPlanning(now);
    return;
  }
  if (!job.floating && now + secondsToNs(budget_.marginS()) > job.branch_ns) {
    ++counters_.plans_late;
    replan(job.attempt, true, now,
           "plan took " + ms(plan_time_s) + ", missing its splice point (budget now " + ms(budget_.budgetS()) + ")");
    return;
  }

  const std::uint64_t program_id = next_program_id_++;
  Segment segment{motion.trajectory, id, job.branch_ns};
  auto spliced = Program::splice(mirror_, SpliceRequest{now, std::move(segment), job.floating, program_id});
  if (!spliced) {
    waiting_ = job.attempt;  // no room in the chain: wait for it to age out (onTimer)
    return;
  }
  if (auto it = open_.find(id); it != open_.end()) {
    it->second.times_ms = motion.times_ms;
    it->second.duration_s = motion.trajectory->durationS();
  }
  ++counters_.plans_succeeded;
  sink_.postProgram(std::make_unique<Program>(spliced->program));
  stage_ = Posted{program_id, std::move(spliced->program), std::move(job.attempt), std::move(spliced->dropped_requests),
                  std::move(spliced->pruned_requests)};
}

void GoalCoordinator::onAdopted(Posted posted, const StreamEvent& event, MonoNs now) {
  mirror_ = std::move(posted.program);
  // The streamer decided where a floating plan starts; the mirror takes its start time.
  mirror_.resolveFloatingStart(event.start_ns);
  const std::int64_t id = posted.attempt.goal.request_id;
  // A pruned segment no tick streamed has no kExecuting to end it: end it here.
  for (const auto& [over, successor] : posted.pruned) finish(over, GoalStatus::kCancelled, superseded(successor));
  for (std::int64_t dropped : posted.dropped) finish(dropped, GoalStatus::kCancelled, superseded(id));
  const Segment& added = mirror_.segment(mirror_.segmentCount() - 1);
  sink_.publishTrajectory(id, added.source, added.start_ns);
  startPlanning(now);
}

void GoalCoordinator::onRejected(Posted posted, const StreamEvent& event, MonoNs now) {
  if (shutDown()) return;  // the goal has its final status; nothing is re-planned
  if (const std::string* reason = stopReason()) {
    finish(posted.attempt.goal.request_id, GoalStatus::kCancelled, "motion stopped: " + *reason);
    return;
  }
  const bool late = event.reject_reason == RejectReason::kLate;
  if (late) ++counters_.plans_late;
  replan(posted.attempt, late, now,
         "the streamer did not take the plan (" + std::string(toString(event.reject_reason)) + ")");
}

void GoalCoordinator::cancelScheduled(const std::string& reason) {
  std::vector<std::int64_t> ids;
  for (int i = 0; i < mirror_.segmentCount(); ++i) ids.push_back(mirror_.segment(i).request_id);
  if (const auto* posted = std::get_if<Posted>(&stage_)) ids.push_back(posted->attempt.goal.request_id);
  if (executing_) ids.push_back(*executing_);
  for (std::int64_t id : ids) finish(id, GoalStatus::kCancelled, reason);
}

void GoalCoordinator::onStopped(const StreamEvent& event) {
  const std::string reason(toString(event.gate_reason));
  cancelScheduled("motion stopped: " + reason);
  if (waiting_) {
    finish(waiting_->goal.request_id, GoalStatus::kCancelled, "motion stopped: " + reason);
    waiting_.reset();
  }
  mirror_ = Program::holdAt(event.epoch, event.position);
  if (!shutDown()) stream_ = Stopped{reason};
}

void GoalCoordinator::onHolding(const StreamEvent& event, MonoNs now) {
  // The shutdown hold replaces every program: what was scheduled will not run.
  if (event.hold_cause == HoldCause::kShutdown) cancelScheduled("daemon shutting down");
  mirror_ = Program::holdAt(event.epoch, event.position);
  if (shutDown()) return;
  stream_ = Streaming{};
  startPlanning(now);
}

void GoalCoordinator::onExecuting(const StreamEvent& event, MonoNs now) {
  if (executing_ && *executing_ != event.request_id) {
    finish(*executing_, GoalStatus::kCancelled, superseded(event.request_id));
  }
  // Segments before this one that no tick sampled (spliced less than a period apart) are over.
  for (int i = 0; i < mirror_.segmentCount() && mirror_.segment(i).request_id != event.request_id; ++i) {
    finish(mirror_.segment(i).request_id, GoalStatus::kCancelled, superseded(event.request_id));
  }
  if (open_.count(event.request_id) != 0 && executing_ != event.request_id) {
    executing_ = event.request_id;
    publish(event.request_id, GoalStatus::kExecuting);
  }
  startPlanning(now);
}

void GoalCoordinator::onStreamEvent(const StreamEvent& event, MonoNs now) {
  switch (event.kind) {
    case StreamEventKind::kAdopted:
    case StreamEventKind::kRejected: {
      auto* posted = std::get_if<Posted>(&stage_);
      if (posted == nullptr || posted->program_id != event.program_id) return;  // not the program posted
      Posted taken = std::move(*posted);
      stage_ = Idle{};
      if (event.kind == StreamEventKind::kAdopted) {
        onAdopted(std::move(taken), event, now);
      } else {
        onRejected(std::move(taken), event, now);
      }
      return;
    }
    case StreamEventKind::kExecuting: onExecuting(event, now); return;
    case StreamEventKind::kDone:
      finish(event.request_id, GoalStatus::kDone, {});
      startPlanning(now);
      return;
    case StreamEventKind::kStopped: onStopped(event); return;
    case StreamEventKind::kHolding: onHolding(event, now); return;
    case StreamEventKind::kFault:
      sink_.note(NoteLevel::kWarn, "fault: setpoint of request " + std::to_string(event.request_id) +
                                       " is not finite or does not fit the setpoint frame; motion stopped");
      return;
  }
}

void GoalCoordinator::onTimer(MonoNs now) { startPlanning(now); }

void GoalCoordinator::onShutdown(MonoNs /*now*/) {
  stream_ = ShutDown{};
  waiting_.reset();
  std::vector<std::int64_t> ids;
  for (const auto& [id, goal] : open_) ids.push_back(id);
  for (std::int64_t id : ids) finish(id, GoalStatus::kCancelled, "daemon shutting down");
}

}  // namespace cyber::daemon

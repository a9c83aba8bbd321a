#include "cyber/daemon/goal_coordinator.hpp"

#include <sstream>
#include <utility>

namespace cyber::daemon {

namespace {

std::string superseded(std::int64_t by) { return "superseded by request " + std::to_string(by); }

std::string ms(double seconds) {
  std::ostringstream out;
  out.precision(1);
  out << std::fixed << seconds * 1e3 << " ms";
  return out.str();
}

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
  if (shut_down_) {
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
  if (pending_) finish(pending_->goal.request_id, GoalStatus::kCancelled, superseded(goal.request_id));
  pending_ = Pending{valid.value(), 0, false};
  tryStart(now);
}

void GoalCoordinator::tryStart(MonoNs now) {
  if (!pending_ || in_flight_ || posted_ || stopped_) return;
  // A chain without room for one more segment ages out within a budget; onTimer retries.
  if (!Program::splice(mirror_, SpliceRequest{now, Segment{nullptr, -1, kNever}, true, 0})) return;

  InFlight job;
  job.job_id = next_job_id_++;
  job.pending = *pending_;
  job.base_id = mirror_.id;
  job.base_epoch = mirror_.epoch;
  pending_.reset();

  MotionRequest request;
  request.goal = job.pending.goal.q;
  request.pieces = job.pending.goal.pieces;
  request.scene = job.pending.goal.scene;
  const MonoNs branch = now + secondsToNs(budget_.budgetS());
  const ProgramSample at_branch = mirror_.sample(branch, HoldModel(robot_));
  if (job.pending.from_rest || !at_branch.moving) {
    // From rest: no deadline, the plan starts when it is ready (or when the motion ends).
    job.floating = true;
    request.start = mirror_.restPosition();
  } else {
    job.floating = false;
    job.branch_ns = branch;
    request.start = at_branch.setpoints.position;
    request.start_velocity = at_branch.setpoints.velocity;
  }
  if (job.pending.attempt == 0) publish(job.pending.goal.request_id, GoalStatus::kPlanning);
  PlanJob plan_job{job.job_id, job.pending.goal.request_id, request};
  in_flight_ = job;
  sink_.startPlanning(plan_job);
}

void GoalCoordinator::replan(const Pending& pending, bool late, MonoNs now, const std::string& why) {
  if (pending_) {
    // A newer goal is already waiting: this one is superseded rather than re-planned.
    finish(pending.goal.request_id, GoalStatus::kCancelled, superseded(pending_->goal.request_id));
    return;
  }
  Pending next = pending;
  ++next.attempt;
  if (late && next.attempt >= settings_.max_late_attempts && !next.from_rest) {
    next.from_rest = true;
    sink_.note(NoteLevel::kWarn, "request " + std::to_string(pending.goal.request_id) + ": " + why +
                                     "; finishing the running motion and planning from where it ends");
  } else {
    sink_.note(late ? NoteLevel::kWarn : NoteLevel::kInfo,
               "request " + std::to_string(pending.goal.request_id) + ": " + why + "; re-planning from a later point");
  }
  pending_ = next;
  tryStart(now);
}

void GoalCoordinator::onPlanResult(std::uint64_t job_id, planner::Result<PlannedMotion> result, double plan_time_s,
                                   MonoNs now) {
  if (!in_flight_ || in_flight_->job_id != job_id) return;
  InFlight job = std::move(*in_flight_);
  in_flight_.reset();
  budget_.record(plan_time_s);
  const std::int64_t id = job.pending.goal.request_id;

  if (stopped_) {
    finish(id, GoalStatus::kCancelled, "motion stopped while planning: " + stop_reason_);
    return;
  }
  if (mirror_.id != job.base_id || mirror_.epoch != job.base_epoch) {
    replan(job.pending, false, now, "the running motion changed while planning");
    return;
  }
  if (!result) {
    const planner::PlanError& error = result.error();
    finish(id, statusOfPlanError(error.status), std::string(planner::toString(error.status)) + ": " + error.reason);
    tryStart(now);
    return;
  }
  PlannedMotion motion = std::move(result).value();
  if (!motion.trajectory) {
    finish(id, GoalStatus::kFailed, "internal error: the planner returned no trajectory");
    tryStart(now);
    return;
  }
  if (!job.floating && now + secondsToNs(budget_.marginS()) > job.branch_ns) {
    ++counters_.plans_late;
    replan(job.pending, true, now,
           "plan took " + ms(plan_time_s) + ", missing its splice point (budget now " + ms(budget_.budgetS()) + ")");
    return;
  }

  Posted posted;
  posted.program_id = next_program_id_++;
  posted.pending = job.pending;
  Segment segment{motion.trajectory, id, job.branch_ns};
  auto spliced = Program::splice(mirror_, SpliceRequest{now, std::move(segment), job.floating, posted.program_id});
  if (!spliced) {
    pending_ = job.pending;  // no room in the chain: wait for it to age out (onTimer)
    return;
  }
  posted.program = std::move(spliced->program);
  posted.dropped = std::move(spliced->dropped_requests);
  if (auto it = open_.find(id); it != open_.end()) {
    it->second.times_ms = motion.times_ms;
    it->second.duration_s = motion.trajectory->durationS();
  }
  ++counters_.plans_succeeded;
  sink_.postProgram(std::make_unique<Program>(posted.program));
  posted_ = std::move(posted);
}

void GoalCoordinator::cancelScheduled(const std::string& reason) {
  std::vector<std::int64_t> ids;
  for (int i = 0; i < mirror_.segmentCount(); ++i) ids.push_back(mirror_.segment(i).request_id);
  if (posted_) ids.push_back(posted_->pending.goal.request_id);
  if (executing_) ids.push_back(*executing_);
  for (std::int64_t id : ids) finish(id, GoalStatus::kCancelled, reason);
}

void GoalCoordinator::onStreamEvent(const StreamEvent& event, MonoNs now) {
  switch (event.kind) {
    case StreamEventKind::kAdopted: {
      if (!posted_ || posted_->program_id != event.program_id) return;
      Posted posted = std::move(*posted_);
      posted_.reset();
      mirror_ = std::move(posted.program);
      mirror_.resolveFloatingStart(event.time_ns);  // the streamer resolved it the same way
      const std::int64_t id = posted.pending.goal.request_id;
      for (std::int64_t dropped : posted.dropped) finish(dropped, GoalStatus::kCancelled, superseded(id));
      const Segment& added = mirror_.segment(mirror_.segmentCount() - 1);
      sink_.publishTrajectory(id, added.source, added.start_ns);
      tryStart(now);
      return;
    }
    case StreamEventKind::kRejected: {
      if (!posted_ || posted_->program_id != event.program_id) return;
      Pending pending = posted_->pending;
      posted_.reset();
      if (stopped_) {
        finish(pending.goal.request_id, GoalStatus::kCancelled, "motion stopped: " + stop_reason_);
        tryStart(now);
        return;
      }
      const bool late = event.reject_reason == RejectReason::kLate;
      if (late) ++counters_.plans_late;
      replan(pending, late, now, "the streamer did not take the plan (" + std::string(toString(event.reject_reason)) + ")");
      return;
    }
    case StreamEventKind::kExecuting: {
      if (executing_ && *executing_ != event.request_id) {
        finish(*executing_, GoalStatus::kCancelled, superseded(event.request_id));
      }
      // Segments before this one that no tick sampled (spliced less than a period apart) are over.
      for (int i = 0; i < mirror_.segmentCount() && mirror_.segment(i).request_id != event.request_id; ++i) {
        finish(mirror_.segment(i).request_id, GoalStatus::kCancelled, superseded(event.request_id));
      }
      if (auto it = open_.find(event.request_id); it != open_.end() && !it->second.executing) {
        it->second.executing = true;
        executing_ = event.request_id;
        publish(event.request_id, GoalStatus::kExecuting);
      }
      tryStart(now);
      return;
    }
    case StreamEventKind::kDone:
      finish(event.request_id, GoalStatus::kDone, {});
      tryStart(now);
      return;
    case StreamEventKind::kStopped:
      stopped_ = true;
      stop_reason_ = std::string(toString(event.gate_reason));
      cancelScheduled("motion stopped: " + stop_reason_);
      if (pending_) {
        finish(pending_->goal.request_id, GoalStatus::kCancelled, "motion stopped: " + stop_reason_);
        pending_.reset();
      }
      mirror_ = Program::holdAt(event.epoch, event.position);
      return;
    case StreamEventKind::kHolding: {
      if (event.hold_cause == HoldCause::kShutdown) {
        cancelScheduled("daemon shutting down");
      }
      stopped_ = false;
      mirror_ = Program::holdAt(event.epoch, event.position);
      tryStart(now);
      return;
    }
    case StreamEventKind::kFault:
      sink_.note(NoteLevel::kWarn, "fault: setpoint of request " + std::to_string(event.request_id) +
                                       " is not finite or does not fit the setpoint frame; motion stopped");
      return;
  }
}

void GoalCoordinator::onTimer(MonoNs now) { tryStart(now); }

void GoalCoordinator::onShutdown(MonoNs /*now*/) {
  shut_down_ = true;
  pending_.reset();
  std::vector<std::int64_t> ids;
  for (const auto& [id, goal] : open_) ids.push_back(id);
  for (std::int64_t id : ids) finish(id, GoalStatus::kCancelled, "daemon shutting down");
}

}  // namespace cyber::daemon

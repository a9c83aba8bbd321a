#include "cyber/daemon/goal_coordinator.hpp"

#include <fmt/format.h>

#include <iterator>
#include <utility>

namespace cyber::daemon {

namespace {

std::string superseded(std::int64_t by) { return "superseded by request " + std::to_string(by); }

std::string ms(double seconds) { return fmt::format("{:.1f} ms", seconds * 1e3); }

// The reasons of docs/lcm.md, "Cancel and manual override".
const std::string kHoldReason = "cancelled by ARM_CANCEL: hold";
const std::string kReleaseReason = "cancelled by ARM_CANCEL: release (manual override)";
const std::string kReleasedStop = "released by ARM_CANCEL (manual override)";

std::string requestText(std::int64_t request_id) {
  return request_id == CancelRequest::kActive ? std::string("the active goal")
                                              : "request " + std::to_string(request_id);
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

std::optional<std::string_view> GoalCoordinator::stopReason() const {
  if (released()) return kReleasedStop;
  const auto* stopped = std::get_if<Stopped>(&stream_);
  if (stopped == nullptr) return std::nullopt;
  return stopped->reason;
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
  auto valid = validateGoal(goal, robot_, settings_.poses);
  if (!valid) {
    reject(goal.request_id, std::string(planner::toString(valid.error().status)) + ": " + valid.error().message);
    return;
  }
  if (shutDown()) {
    reject(goal.request_id, "daemon shutting down");
    return;
  }
  // kReleased comes only when nothing else closes the gate: a valid goal ends the release.
  if (!gate.open() && gate.reason != GateReason::kReleased) {
    reject(goal.request_id, "no motion allowed: " + std::string(toString(gate.reason)));
    return;
  }
  if (released()) endRelease();
  // A sender that reuses an id still open replaces that goal.
  if (open_.count(goal.request_id) != 0) finish(goal.request_id, GoalStatus::kCancelled, superseded(goal.request_id));
  open_[goal.request_id] = OpenGoal{};
  publish(goal.request_id, GoalStatus::kAccepted);

  // Latest wins among the goals waiting for the worker. The plan being computed is not thrown
  // away: it runs when ready and the newest goal is spliced into it, so a steady stream of goals
  // faster than the planner still moves the mechanism instead of starving it.
  // A stop waiting for the worker gives way too: the goal is planned from the commanded state a
  // budget ahead, as the stop would have been.
  if (waiting_ && !waiting_->stop) {
    finish(waiting_->goal.request_id, GoalStatus::kCancelled, superseded(goal.request_id));
  }
  waiting_ = Attempt{valid.value(), 0, false, false, false, {}};
  startPlanning(now);
}

void GoalCoordinator::startPlanning(MonoNs now) {
  if (!waiting_ || !std::holds_alternative<Idle>(stage_) || !std::holds_alternative<Streaming>(stream_)) return;
  // A chain without room for one more segment ages out within a budget; onTimer retries.
  if (!Program::splice(mirror_, SpliceRequest{now, Segment{nullptr, -1, kNever}, true, 0})) return;

  const MonoNs branch = now + secondsToNs(budget_.budgetS());
  const ProgramSample at_branch = mirror_.sample(branch, HoldModel(robot_));
  Attempt attempt = std::move(*waiting_);
  waiting_.reset();
  if (attempt.stop && !prepareStop(attempt, at_branch)) return;
  Planning job;
  job.job_id = next_job_id_++;
  job.attempt = std::move(attempt);
  job.base_id = mirror_.id;
  job.base_epoch = mirror_.epoch;

  MotionRequest request;
  request.kind = job.attempt.stop ? MotionKind::kStop : MotionKind::kMove;
  request.goal = job.attempt.stop ? at_branch.setpoints.position : job.attempt.goal.q;
  request.pieces = job.attempt.goal.pieces;
  request.scene = job.attempt.goal.scene;
  request.scene_offset_m = job.attempt.goal.scene_offset_m;
  if (!job.attempt.stop && (job.attempt.from_rest || !at_branch.moving)) {
    // From rest: no deadline, the plan starts when it is ready (or when the motion ends).
    job.floating = true;
    if (const MonoNs end = mirror_.endNs(); !job.attempt.from_rest && end > now) {
      // Said, because a goal not spliced into the running motion is otherwise a surprise: a
      // slow planner's budget outlasts the motion (docs/operations.md, "What it does").
      sink_.note(NoteLevel::kInfo, "request " + std::to_string(job.attempt.goal.request_id) +
                                       ": the running motion ends in " + ms(nsToSeconds(end - now)) +
                                       ", within the planning budget of " + ms(budget_.budgetS()) +
                                       "; planning from where it ends");
    }
    request.start = mirror_.restPosition();
    request.start_velocity = JointVector::Zero(request.start.size());
  } else {
    job.floating = false;
    job.branch_ns = branch;
    request.start = at_branch.setpoints.position;
    request.start_velocity = at_branch.setpoints.velocity;
  }
  if (job.attempt.attempt == 0 && !job.attempt.stop) publish(job.attempt.goal.request_id, GoalStatus::kPlanning);
  const PlanJob plan_job{job.job_id, job.attempt.goal.request_id, request};
  stage_ = std::move(job);
  sink_.startPlanning(plan_job);
}

// A stop: what the streamer will run at the branch decides. Segments abut (a fixed splice starts
// inside a moving segment, a floating one where the previous ends), so a program at rest at the
// branch stays at rest after it: the hold it streams then is the stop.
bool GoalCoordinator::prepareStop(Attempt& stop, const ProgramSample& at_branch) {
  if (!at_branch.moving) {
    sink_.note(NoteLevel::kDebug, "ARM_CANCEL hold: the mechanism is at rest; holding there");
    return false;
  }
  const std::string stopped = "ARM_CANCEL hold: request " + std::to_string(at_branch.request_id);
  if (stop.from_rest) {
    sink_.note(NoteLevel::kWarn, stopped +
                                     ": no stop was planned in time; the running motion (collision-free) "
                                     "continues to its end at rest");
    return false;
  }
  const auto world = worlds_.find(at_branch.request_id);
  if (world == worlds_.end()) {
    sink_.note(NoteLevel::kWarn, stopped +
                                     ": its collision world is not known; the running motion continues to its "
                                     "end at rest");
    return false;
  }
  stop.goal.request_id = at_branch.request_id;
  stop.goal.pieces = world->second.pieces;
  stop.goal.scene = world->second.scene;
  stop.goal.scene_offset_m = world->second.scene_offset_m;
  return true;
}

void GoalCoordinator::replan(const Attempt& attempt, bool late, MonoNs now, const std::string& why) {
  if (waiting_) {
    // A newer goal (or stop) is already waiting: this one is superseded rather than re-planned.
    if (!attempt.stop) finish(attempt.goal.request_id, GoalStatus::kCancelled, superseded(waiting_->goal.request_id));
    return;
  }
  Attempt next = attempt;
  ++next.attempt;
  const std::string who = (attempt.stop ? "ARM_CANCEL hold, stop of request " : "request ") +
                          std::to_string(attempt.goal.request_id) + ": ";
  if (late && next.attempt >= settings_.max_late_attempts && !next.from_rest) {
    next.from_rest = true;  // a stop gives up here (prepareStop): the running motion ends at rest
    sink_.note(NoteLevel::kWarn, who + why +
                                     (attempt.stop ? std::string("; no more attempts")
                                                   : std::string("; finishing the running motion and planning from "
                                                                 "where it ends")));
  } else {
    sink_.note(late ? NoteLevel::kWarn : NoteLevel::kInfo, who + why + "; re-planning from a later point");
  }
  waiting_ = next;
  startPlanning(now);
}

bool GoalCoordinator::retryFromRest(const Attempt& attempt, const planner::PlanError& error) {
  // A rejection is the goal's own fault (bad input, a goal out of range or in collision): no
  // start changes it.
  if (statusOfPlanError(error.status) != GoalStatus::kFailed) return false;
  const std::string what = std::string(planner::toString(error.status)) + ": " + error.message;
  if (waiting_) {
    // A newer goal is already waiting: it is planned instead, from the same motion.
    finish(attempt.goal.request_id, GoalStatus::kCancelled, superseded(waiting_->goal.request_id));
    return true;
  }
  Attempt next = attempt;
  ++next.attempt;
  next.from_rest = true;
  next.moving_start_failure = what;
  sink_.note(NoteLevel::kInfo, "request " + std::to_string(attempt.goal.request_id) + ": from the moving start " +
                                   what + "; finishing the running motion and planning from where it ends");
  waiting_ = std::move(next);  // the caller starts planning it
  return true;
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
  if (job.attempt.cancelled) {
    sink_.note(NoteLevel::kDebug, "request " + std::to_string(id) + ": plan dropped (cancelled by ARM_CANCEL)");
    startPlanning(now);
    return;
  }
  if (const auto reason = stopReason()) {
    if (!job.attempt.stop) finish(id, GoalStatus::kCancelled, "motion stopped while planning: " + std::string(*reason));
    return;
  }
  if (mirror_.id != job.base_id || mirror_.epoch != job.base_epoch) {
    replan(job.attempt, false, now, "the running motion changed while planning");
    return;
  }
  if (!result) {
    const planner::PlanError& error = result.error();
    const std::string what = std::string(planner::toString(error.status)) + ": " + error.message;
    if (job.attempt.stop) {
      // The running motion is collision-free and ends at rest: finishing it is the safe answer.
      sink_.note(NoteLevel::kWarn, "ARM_CANCEL hold: no admissible stop for request " + std::to_string(id) + " (" +
                                       what + "); the running motion continues to its end at rest");
    } else if (job.floating || !retryFromRest(job.attempt, error)) {
      const std::string why = job.attempt.moving_start_failure.empty()
                                  ? what
                                  : what + " (from the moving start: " + job.attempt.moving_start_failure + ")";
      finish(id, statusOfPlanError(error.status), why);
    }
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
  worlds_[id] = World{job.attempt.goal.pieces, job.attempt.goal.scene, job.attempt.goal.scene_offset_m};
  if (job.attempt.stop) {
    ++counters_.stops_planned;
    sink_.note(NoteLevel::kInfo, "ARM_CANCEL hold: request " + std::to_string(id) + " brakes to rest in " +
                                     ms(motion.trajectory->durationS()));
  } else {
    ++counters_.plans_succeeded;
  }
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
  // Only the worlds of segments that may still run are kept.
  for (auto it = worlds_.begin(); it != worlds_.end();) {
    bool in_mirror = false;
    for (int i = 0; i < mirror_.segmentCount(); ++i) in_mirror |= mirror_.segment(i).request_id == it->first;
    it = in_mirror ? std::next(it) : worlds_.erase(it);
  }
  const Segment& added = mirror_.segment(mirror_.segmentCount() - 1);
  sink_.publishTrajectory(id, added.source, added.start_ns);
  startPlanning(now);
}

void GoalCoordinator::onRejected(Posted posted, const StreamEvent& event, MonoNs now) {
  if (shutDown()) return;          // the goal has its final status; nothing is re-planned
  if (posted.attempt.cancelled) {  // ARM_CANCEL answered it already; a stop may wait for the worker
    startPlanning(now);
    return;
  }
  if (const auto reason = stopReason()) {
    if (!posted.attempt.stop)
      finish(posted.attempt.goal.request_id, GoalStatus::kCancelled, "motion stopped: " + std::string(*reason));
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
  mirror_ = Program::holdAt(event.epoch, event.position);
  worlds_.clear();
  // A stop for a release: the goals open at the release were cancelled then, and a goal open now
  // came after it, ended it and waits for the hold at the measured position.
  if (event.gate_reason == GateReason::kReleased) return;
  const std::string reason(toString(event.gate_reason));
  cancelScheduled("motion stopped: " + reason);
  if (waiting_) {
    if (!waiting_->stop) finish(waiting_->goal.request_id, GoalStatus::kCancelled, "motion stopped: " + reason);
    waiting_.reset();
  }
  if (!shutDown() && !released()) stream_ = Stopped{reason};
}

void GoalCoordinator::onHolding(const StreamEvent& event, MonoNs now) {
  // The shutdown hold replaces every program: what was scheduled will not run.
  if (event.hold_cause == HoldCause::kShutdown) cancelScheduled("daemon shutting down");
  mirror_ = Program::holdAt(event.epoch, event.position);
  worlds_.clear();
  if (shutDown() || released()) return;
  // A hold the streamer took before it saw the latest release or its end: the stream restarts
  // with the hold after that.
  if (event.release_generation != release_generation_) return;
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

void GoalCoordinator::cancelOpen(const std::string& reason) {
  if (waiting_) {
    if (!waiting_->stop) finish(waiting_->goal.request_id, GoalStatus::kCancelled, reason);
    waiting_.reset();
  }
  if (auto* planning = std::get_if<Planning>(&stage_)) planning->attempt.cancelled = true;
  if (auto* posted = std::get_if<Posted>(&stage_)) posted->attempt.cancelled = true;
  std::vector<std::int64_t> ids;
  for (const auto& [id, goal] : open_) ids.push_back(id);
  for (std::int64_t id : ids) {
    finish(id, GoalStatus::kCancelled, reason);
    ++counters_.goals_cancelled;
  }
}

void GoalCoordinator::release() {
  ++release_generation_;  // odd: released
  sink_.setReleaseGeneration(release_generation_);
  stream_ = Released{};
  sink_.note(NoteLevel::kInfo, "manual override (ARM_CANCEL release): no setpoints are streamed until the next goal");
}

void GoalCoordinator::endRelease() {
  ++release_generation_;  // even: the streamer holds the measured position, then the goal is planned
  sink_.setReleaseGeneration(release_generation_);
  stream_ = Stopped{"the manual override is ending: waiting for the hold at the measured position"};
  sink_.note(NoteLevel::kInfo, "manual override ended by a goal: holding the measured position");
}

void GoalCoordinator::onCancel(const CancelRequest& cancel, MonoNs now) {
  const std::string what = cancel.action == CancelAction::kHold ? "hold" : "release";
  if (shutDown() || released()) {
    sink_.note(NoteLevel::kDebug, "ARM_CANCEL " + what + " for " + requestText(cancel.request_id) +
                                      " ignored: " + (shutDown() ? "shutting down" : "already released"));
    return;
  }
  const bool names_open =
      cancel.request_id == CancelRequest::kActive ? !open_.empty() : open_.count(cancel.request_id) != 0;
  // A release with -1 takes the joints over even when no goal is open (the daemon is holding).
  const bool applies =
      names_open || (cancel.action == CancelAction::kRelease && cancel.request_id == CancelRequest::kActive);
  if (!applies) {
    sink_.note(NoteLevel::kDebug, "ARM_CANCEL " + what + " for " + requestText(cancel.request_id) +
                                      " ignored: no such open goal (already final or unknown)");
    return;
  }
  if (cancel.action == CancelAction::kRelease) {
    cancelOpen(kReleaseReason);
    release();
    return;
  }
  cancelOpen(kHoldReason);
  // Stopped: the streamer sends nothing now and holds the measured position when it restarts.
  if (!std::holds_alternative<Streaming>(stream_)) return;
  Attempt stop;
  stop.goal.request_id = CancelRequest::kActive;
  stop.stop = true;
  waiting_ = stop;
  startPlanning(now);
}

void GoalCoordinator::onShutdown(MonoNs /*now*/) {
  stream_ = ShutDown{};
  waiting_.reset();
  std::vector<std::int64_t> ids;
  for (const auto& [id, goal] : open_) ids.push_back(id);
  for (std::int64_t id : ids) finish(id, GoalStatus::kCancelled, "daemon shutting down");
}

}  // namespace cyber::daemon

#include "motion/moving_start_strategies.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "motion/fastest_stop.hpp"
#include "motion/timed_plan.hpp"
#include "path/path_folds.hpp"
#include "timing/topp.hpp"

namespace cyber::planner {
namespace {

// A junction is tried only in the middle half between two samples (within a quarter step of the
// midpoint), where the trapezoid across an acceleration jump errs by at most a quarter of it.
constexpr double kMiddleHalf = 0.25;

bool requestError(PlanStatus status) {
  return status == PlanStatus::kInvalidInput || status == PlanStatus::kStartOutOfRange ||
         status == PlanStatus::kGoalOutOfRange || status == PlanStatus::kStartInCollision ||
         status == PlanStatus::kGoalInCollision;
}

// The rest-to-rest plan from where `stop` ends, after it.
Result<Plan> planAfterStop(const MovingStartInputs& in, const Trajectory& stop) {
  return joinAfter(PlanMethod::kStoppedFirst, in.request, stop,
                   timedPath(in.model, in.paths, restOf(stop), in.request.goal, in.request.pieces,
                             JointVector::Zero(in.model.jointCount())));
}

// The stop and the onward paths, prepared: what the stop-first candidate times.
struct StopAndOnward {
  Trajectory stop;
  std::vector<PlannedPath> onward;
  double stop_ms = 0.0;
};

// The stop-first candidate timed. At the instant of rest the acceleration jumps (braking, then
// leaving along another direction); sampled every 1 ms, the columns then agree only when the jump
// falls near the middle between samples (the trapezoid of the two samples around it is then close
// to the true change of velocity), so when they do not, the stop is made gentle enough to move
// the junction later (docs/moving-starts.md).
Result<Plan> timeStopFirst(const MovingStartInputs& in, const StopAndOnward& prepared) {
  const Trajectory& stop = prepared.stop;
  const Result<Plan> onward = timePaths(in.model, prepared.onward, JointVector::Zero(in.model.jointCount()));
  Result<Plan> plan = joinAfter(PlanMethod::kStoppedFirst, in.request, stop, onward);
  const MotionSettings& settings = in.model.planner.motion;
  const double steps = stop.duration_s() / settings.consistency_step_s;
  // The later instants of rest in the middle half between two samples (where the trapezoid across
  // the jump errs by at most a quarter of it), earliest first.
  int tries = 0;
  for (int i = 1; i <= settings.gentler_steps && tries < settings.gentler_tries && plan &&
                  !columnsAgree(settings, *plan.value().trajectory);
       ++i) {
    const double target = steps + settings.gentler_step * i;
    if (std::abs(target - std::floor(target) - 0.5) > kMiddleHalf) continue;
    ++tries;
    Result<Trajectory> gentler = stretchedStop(in.model, in.paths.world(in.request.pieces), stop, target / steps);
    plan = gentler ? planAfterStop(in, gentler.value()) : gentler.error();
  }
  // The junction is not the only jump: the trapezoid's errors add up over the whole move, so a
  // short move after a short stop may still disagree. Slowing the onward plan from the fastest
  // stop moves each of its jumps against the samples by a different fraction of a step (as a
  // short move from rest is slowed); the shortest slowdown whose joined columns agree.
  if (onward && (!plan || !columnsAgree(settings, *plan.value().trajectory))) {
    Result<Plan> joined = inconsistentPlan();
    const auto joined_agrees = [&](const Trajectory& slower) {
      Plan slowed = onward.value();
      slowed.trajectory = std::make_shared<const Trajectory>(slower);
      slowed.method.repairs |= PlanMethod::kSlowedAfterStop;
      joined = joinAfter(PlanMethod::kStoppedFirst, in.request, stop, std::move(slowed));
      return joined && columnsAgree(settings, *joined.value().trajectory);
    };
    if (shortestSlowdown(in.model, *onward.value().trajectory, settings.onward_slower_steps, joined_agrees)) {
      plan = std::move(joined);
    }
  }
  if (plan) plan.value().times_ms.topp += prepared.stop_ms;
  return plan;
}

// A candidate with its columns' verdict, judged once. Candidates rank by agreeing columns first,
// then by duration.
struct Judged {
  Result<Plan> plan = inconsistentPlan();
  bool timed = false;
  bool agrees = false;
  [[nodiscard]] std::pair<int, double> rank() const {
    return {agrees ? 0 : 1, plan ? plan.value().trajectory->duration_s() : std::numeric_limits<double>::infinity()};
  }
  // What this candidate promises the others must beat: its duration once timed and agreeing,
  // nothing once timed otherwise, its estimate before.
  [[nodiscard]] double promise_s(const MovingStartCandidate& candidate) const {
    if (!timed) return candidate.refused ? std::numeric_limits<double>::infinity() : candidate.estimate_s;
    return agrees ? plan.value().trajectory->duration_s() : std::numeric_limits<double>::infinity();
  }
};

}  // namespace

// Leaving along the velocity is timed on the search's path alone: the candidate that stops first
// searches the alternatives (docs/moving-starts.md, "Planning time").
MovingStartCandidate leaveAlongVelocity(const MovingStartInputs& in) {
  const PlanRequest& request = in.request;
  Result<std::vector<PlannedPath>> found =
      in.paths.candidates(request.start, request.goal, request.pieces, request.start_velocity, PathAlternatives::kNone);
  MovingStartCandidate out;
  if (!found) {
    out.refused = found.error();
    return out;
  }
  const MotionSettings& settings = in.model.planner.motion;
  const double fold_spacing = in.model.planner.smoothing.waypoint_spacing / settings.fold_samples_per_waypoint;
  if (!found.value().empty() && sharpestTurnCosine(*found.value().front().path, fold_spacing) < settings.fold_cosine) {
    // The path folds back on itself (the goal lies behind the motion): the mechanism comes to rest
    // at the fold, as stopping first does with the fastest stop, and TOPP converges badly on the
    // fold. Timed only when stopping first has no plan (its braking line may run into a joint
    // limit that the fold, a little earlier, does not reach).
    out.estimate_s = std::numeric_limits<double>::infinity();
    out.lower_bound_s = out.estimate_s;
  } else {
    out.estimate_s = estimatedSeconds(in.model, found, request.start_velocity);
    out.lower_bound_s = settings.moving_estimate_low * out.estimate_s;
  }
  auto paths = std::make_shared<const std::vector<PlannedPath>>(std::move(found).value());
  out.time = [in, paths] { return timePaths(in.model, *paths, in.request.start_velocity); };
  return out;
}

// The fastest stop along the velocity, then the rest-to-rest plan from where it stops. Its path
// stage runs here, so that both candidates' estimates decide which are timed.
MovingStartCandidate stopFirst(const MovingStartInputs& in) {
  MovingStartCandidate out;
  const auto stop_start = std::chrono::steady_clock::now();
  ToppSolver solver(in.model.planner.topp);
  Result<Trajectory> stop =
      fastestStop(in.model, in.paths.world(in.request.pieces), in.request.start, in.request.start_velocity, solver);
  const double stop_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - stop_start).count();
  if (!stop) {
    out.refused = stop.error();
    return out;
  }
  Result<std::vector<PlannedPath>> onward =
      in.paths.candidates(restOf(stop.value()), in.request.goal, in.request.pieces);
  if (!onward) {
    out.refused = onward.error();
    return out;
  }
  const double onward_s = estimatedSeconds(in.model, onward, JointVector::Zero(in.model.jointCount()));
  out.estimate_s = stop.value().duration_s() + onward_s;
  out.lower_bound_s = stop.value().duration_s() + in.model.planner.motion.rest_estimate_low * onward_s;
  auto prepared =
      std::make_shared<const StopAndOnward>(StopAndOnward{std::move(stop).value(), std::move(onward).value(), stop_ms});
  out.time = [in, prepared] { return timeStopFirst(in, *prepared); };
  return out;
}

std::span<const MovingStartStrategy> movingStartStrategies() {
  static constexpr std::array<MovingStartStrategy, 2> kStrategies{{
      {"leaving along the velocity", "keeps the momentum: fastest when the goal lies roughly ahead of the motion",
       &leaveAlongVelocity},
      {"stopping first",
       "exists whenever the mechanism can brake inside its limits and the clearance, and bounds every plan by "
       "stop + rest-to-rest",
       &stopFirst},
  }};
  return kStrategies;
}

Result<Plan> planMovingStart(const MovingStartInputs& in, std::span<const MovingStartStrategy> strategies) {
  std::vector<MovingStartCandidate> candidates;
  candidates.reserve(strategies.size());
  for (const MovingStartStrategy& strategy : strategies) {
    candidates.push_back(strategy.prepare(in));
    // Errors of the request itself (bad poses, a goal in collision) are the same for all.
    const std::optional<PlanError>& refused = candidates.back().refused;
    if (refused && requestError(refused->status)) return *refused;
  }
  std::vector<Judged> judged(candidates.size());
  const auto time = [&](size_t i) {
    judged[i].plan = candidates[i].time();
    judged[i].timed = true;
    judged[i].agrees = judged[i].plan && columnsAgree(in.model.planner.motion, *judged[i].plan.value().trajectory);
  };
  // Each is timed only while its lower bound leaves it a chance against what the others promise.
  for (size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].refused) continue;
    double best_other_s = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < candidates.size(); ++j) {
      if (j != i) best_other_s = std::min(best_other_s, judged[j].promise_s(candidates[j]));
    }
    if (candidates[i].lower_bound_s <= best_other_s) time(i);
  }
  // A candidate left out because another promised more, which did not keep its promise.
  const auto anyAgrees = [&] {
    for (const Judged& j : judged) {
      if (j.agrees) return true;
    }
    return false;
  };
  // A last resort (a candidate that promises nothing: an infinite bound) only when no other has a
  // plan at all, even one whose columns disagree.
  const auto anyPlan = [&] {
    for (const Judged& j : judged) {
      if (j.timed && j.plan) return true;
    }
    return false;
  };
  for (size_t i = 0; i < candidates.size() && !anyAgrees(); ++i) {
    if (candidates[i].refused || judged[i].timed) continue;
    if (std::isinf(candidates[i].lower_bound_s) && anyPlan()) continue;
    time(i);
  }
  size_t best = candidates.size();
  for (size_t i = 0; i < candidates.size(); ++i) {
    if (judged[i].plan && (best == candidates.size() || judged[i].rank() < judged[best].rank())) best = i;
  }
  if (best < candidates.size()) return std::move(judged[best].plan);
  // None serves: say why each failed (a stop into an obstacle or a joint limit, or no way on from
  // where it stops), not only why the first did.
  const auto errorOf = [&](size_t i) -> const PlanError& {
    return candidates[i].refused ? *candidates[i].refused : judged[i].plan.error();
  };
  if (candidates.empty()) return Result<Plan>::failure(PlanStatus::kInvalidInput, "no moving-start strategy");
  PlanError error = errorOf(0);
  for (size_t i = 1; i < candidates.size(); ++i) {
    error.message += "; " + std::string(strategies[i].name) + ": " + errorOf(i).message;
  }
  return error;
}

}  // namespace cyber::planner

#include "cyber/planner/motion_planner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "cyber/planner/fastest_stop.hpp"
#include "cyber/planner/joined_path.hpp"
#include "cyber/planner/trajectory_consistency.hpp"
#include "cyber/planner/weighted_norm.hpp"

namespace cyber::planner {
namespace {

// Columns are judged at the samples of cyber-plan's CSV (docs/moving-starts.md), within 95 % of
// what an independent check of that CSV allows (1 % of the travel, 2 % of the peak speed).
constexpr double kConsistencyStepS = 0.001;
constexpr double kMaxPositionError = 0.0095;
constexpr double kMaxVelocityError = 0.019;
// After the fastest stop, the junction may be moved later by a multiple of this fraction of a
// step, up to kGentlerSteps of them, trying at most kGentlerTries (each redoes the onward plan).
constexpr double kGentlerStep = 0.125;
constexpr int kGentlerSteps = 12;
constexpr int kGentlerTries = 6;
// A rest-to-rest trajectory whose columns disagree is slowed down until its duration has grown by
// a multiple of this fraction of a step, up to kSlowerSteps of them (two steps).
constexpr double kSlowerStep = 0.125;
constexpr int kSlowerSteps = 16;

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

Result<Plan> inconsistent() {
  return Result<Plan>::failure(
      PlanStatus::kSolverNotConverged,
      "the trajectory's velocities or accelerations do not integrate to its positions at 1 ms");
}

bool consistent(const Trajectory& trajectory) {
  const ColumnConsistency c = columnConsistency(trajectory, kConsistencyStepS);
  return c.position_error <= kMaxPositionError && c.velocity_error <= kMaxVelocityError;
}

// A very short move from rest (tens of milliseconds) whose columns disagree at 1 ms: its switch
// from full acceleration to full braking is a large share of its peak speed, and the trapezoid
// across it errs by up to half the jump times the step (docs/moving-starts.md). Slowing it down
// uniformly moves the switch between the samples (by about half the added time), so the shortest
// slowdown that puts it where the columns agree, within the limits, is taken.
std::optional<Trajectory> consistentSlowdown(const RobotModel& model, const Trajectory& trajectory) {
  const double duration = trajectory.duration_s();
  for (int i = 1; i <= kSlowerSteps && duration > 0.0; ++i) {
    Result<Trajectory> slower = slowedDown(trajectory, 1.0 + i * kSlowerStep * kConsistencyStepS / duration);
    if (slower && consistent(slower.value()) && withinDriveLimits(slower.value(), model.planner.topp)) {
      return std::move(slower).value();
    }
  }
  return std::nullopt;
}

// The path stage from `start` leaving along v0, then TOPP along its candidates in the order of
// their estimated time, until one gives a trajectory whose columns agree.
Result<Plan> timedPath(const RobotModel& model, const PathPlanner& paths, const JointVector& start,
                       const JointVector& goal, HeldPieces pieces, const JointVector& v0,
                       PathAlternatives alternatives = PathAlternatives::kSearch) {
  Result<std::vector<PlannedPath>> found = paths.candidates(start, goal, pieces, v0, alternatives);
  if (!found) return found.error();
  // The spline leaves along v0 with unit speed in the metric Sigma, so sqrt(b_start) = |v0|_Sigma.
  const double speed = weightedNorm(v0, model.planner.metric);
  ToppSolver solver(model.planner.topp);
  Result<Plan> fallback = inconsistent();  // the first trajectory, when no candidate's columns agree
  bool have_fallback = false;
  double topp_ms = 0.0;
  for (size_t i = 0; i < found.value().size(); ++i) {
    const PlannedPath& path = found.value()[i];
    const auto topp_start = std::chrono::steady_clock::now();
    Plan plan;
    Result<Trajectory> trajectory =
        solver.solve(path.path, model.elevator_drive, model.arm_drive, speed * speed, &plan.solver);
    topp_ms += msSince(topp_start);
    if (!trajectory) {
      if (i == 0) fallback = trajectory.error();
      continue;
    }
    const bool agree = consistent(trajectory.value());
    plan.trajectory = std::make_shared<const Trajectory>(std::move(trajectory).value());
    plan.waypoints = path.waypoints;
    plan.min_clearance_m = path.min_clearance_m;
    plan.path_method = path.method;
    plan.times_ms.search = path.search_ms;
    plan.times_ms.smooth = path.smooth_ms;
    plan.times_ms.topp = topp_ms;
    if (agree) return plan;
    if (!have_fallback) {
      fallback = std::move(plan);
      have_fallback = true;
    }
  }
  if (!have_fallback) return fallback;
  Plan& plan = fallback.value();
  plan.times_ms.topp = topp_ms;
  if (speed == 0.0) {
    if (std::optional<Trajectory> slower = consistentSlowdown(model, *plan.trajectory)) {
      plan.trajectory = std::make_shared<const Trajectory>(std::move(*slower));
      plan.path_method += ", slowed to agree at 1 ms";
    }
  }
  // A moving start that agrees nowhere is left to the candidate that stops first.
  return fallback;
}

// The rest-to-rest plan from where `stop` ends, after it.
Result<Plan> planAfterStop(const RobotModel& model, const PathPlanner& paths, const PlanRequest& request,
                           const Trajectory& stop) {
  const JointVector rest = stop.path().at(stop.path().length()).q;
  Result<Plan> onward = timedPath(model, paths, rest, request.goal, request.pieces, JointVector::Zero());
  if (!onward) return onward;
  Result<Trajectory> joined = joinAtRest(stop, *onward.value().trajectory);
  if (!joined) return joined.error();
  Plan plan = std::move(onward).value();
  plan.trajectory = std::make_shared<const Trajectory>(std::move(joined).value());
  plan.waypoints.insert(plan.waypoints.begin(), request.start);
  plan.path_method = "stop, then " + plan.path_method;
  return plan;
}

// The candidate that is always there for a moving start (docs/moving-starts.md): the fastest
// stop along v0, then the rest-to-rest plan from where it stops. At the instant of rest the
// acceleration jumps (braking, then leaving along another direction); sampled every 1 ms, the
// columns then agree only when the jump falls near the middle between samples (the trapezoid of
// the two samples around it is then close to the true change of velocity), so when they do not,
// the stop is made gentle enough to move the junction later (docs/moving-starts.md).
Result<Plan> stopThenPlan(const RobotModel& model, const PathPlanner& paths, const PlanRequest& request) {
  const auto stop_start = std::chrono::steady_clock::now();
  ToppSolver solver(model.planner.topp);
  const CollisionWorld& world = paths.world(request.pieces);
  Result<Trajectory> stop = fastestStop(model, world, request.start, request.start_velocity, solver);
  const double stop_ms = msSince(stop_start);
  if (!stop) return stop.error();
  Result<Plan> plan = planAfterStop(model, paths, request, stop.value());
  const double steps = stop.value().duration_s() / kConsistencyStepS;
  // The later instants of rest in the middle half between two samples (where the trapezoid across
  // the jump errs by at most a quarter of it), earliest first.
  int tries = 0;
  for (int i = 1; i <= kGentlerSteps && tries < kGentlerTries && plan && !consistent(*plan.value().trajectory); ++i) {
    const double target = steps + kGentlerStep * i;
    if (std::abs(target - std::floor(target) - 0.5) > 0.25) continue;
    ++tries;
    Result<Trajectory> gentler = stretchedStop(model, world, stop.value(), target / steps);
    plan = gentler ? planAfterStop(model, paths, request, gentler.value()) : gentler.error();
  }
  if (plan) plan.value().times_ms.topp += stop_ms;
  return plan;
}

}  // namespace

Result<MotionPlanner> MotionPlanner::create(const RobotModel& model) {
  if (model.scenes.empty()) return Result<MotionPlanner>::failure(PlanStatus::kInvalidInput, "the robot has no scene");
  if (model.geometry.arm.empty()) {
    return Result<MotionPlanner>::failure(PlanStatus::kInvalidInput, "the robot has no arm geometry");
  }
  MotionPlanner planner;
  planner.model_ = model;
  planner.path_planners_.reserve(model.scenes.size());
  for (const Scene& scene : model.scenes) planner.path_planners_.emplace_back(model, scene);
  return planner;
}

Result<Plan> MotionPlanner::plan(const PlanRequest& request) const {
  const auto start_time = std::chrono::steady_clock::now();
  if (request.scene < 0 || request.scene >= static_cast<int>(path_planners_.size())) {
    return Result<Plan>::failure(PlanStatus::kInvalidInput, "unknown scene index " + std::to_string(request.scene));
  }
  if (!request.start_velocity.allFinite()) {
    return Result<Plan>::failure(PlanStatus::kInvalidInput, "start velocity is not finite");
  }
  const PathPlanner& paths = path_planners_[static_cast<size_t>(request.scene)];
  const bool moving = weightedNorm(request.start_velocity, model_.planner.metric) > 0.0;
  // A moving start leaving along its velocity is timed on the search's path alone: its candidate
  // that stops first searches the alternatives (docs/moving-starts.md, "Planning time").
  Result<Plan> direct = timedPath(model_, paths, request.start, request.goal, request.pieces, request.start_velocity,
                                  moving ? PathAlternatives::kNone : PathAlternatives::kSearch);
  // Errors of the request itself (bad poses, a goal in collision) are the same for both.
  const bool request_error =
      !direct && (direct.status() == PlanStatus::kInvalidInput || direct.status() == PlanStatus::kStartOutOfRange ||
                  direct.status() == PlanStatus::kGoalOutOfRange || direct.status() == PlanStatus::kStartInCollision ||
                  direct.status() == PlanStatus::kGoalInCollision);
  Result<Plan> chosen = std::move(direct);
  if (moving && !request_error) {
    Result<Plan> stopped = stopThenPlan(model_, paths, request);
    // Columns that agree first, then the faster.
    auto rank = [](const Result<Plan>& p) {
      return std::pair{p && consistent(*p.value().trajectory) ? 0 : 1, p.value().trajectory->duration_s()};
    };
    const bool stopped_faster = stopped && (!chosen || rank(stopped) < rank(chosen));
    if (stopped_faster) chosen = std::move(stopped);
  }
  if (!chosen) return chosen;
  Plan plan = std::move(chosen).value();
  plan.times_ms.grid = paths.gridBuildMs(request.pieces);
  plan.times_ms.total = msSince(start_time);
  return plan;
}

}  // namespace cyber::planner

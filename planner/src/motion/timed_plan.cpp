#include "motion/timed_plan.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include <fmt/format.h>

#include "cyber/planner/trajectory.hpp"
#include "elapsed_ms.hpp"
#include "math/weighted_norm.hpp"
#include "path/joined_path.hpp"
#include "timing/path_timing.hpp"
#include "timing/topp.hpp"

namespace cyber::planner {
namespace {

// A very short move from rest (tens of milliseconds) whose columns disagree at 1 ms: its switch
// from full acceleration to full braking is a large share of its peak speed, and the trapezoid
// across it errs by up to half the jump times the step (docs/moving-starts.md). Slowing it down
// uniformly moves the switch between the samples (by about half the added time), so the shortest
// slowdown that puts it where the columns agree, within the limits and what agreeing may cost
// (MotionSettings::max_consistency_cost), is taken.
std::optional<Trajectory> consistentSlowdown(const RobotModel& model, const Trajectory& trajectory) {
  const MotionSettings& settings = model.planner.motion;
  if (trajectory.duration_s() > settings.slower_max_duration_s) return std::nullopt;
  const double step_s = settings.slower_step * settings.consistency_step_s;
  const int affordable = static_cast<int>(std::floor(settings.max_consistency_cost * trajectory.duration_s() / step_s));
  return shortestSlowdown(model, trajectory, std::min(settings.slower_steps, affordable),
                          [&](const Trajectory& slower) { return columnsAgree(settings, slower); });
}

// A move from rest whose columns still disagree: its early acceleration switch (a burst to a
// speed the voltage or a velocity cap holds) lands where the trapezoid across it errs, and a
// uniform slowdown hardly moves an early switch. The start made gentler by gentler_start_step at a
// time, up to gentler_start_steps, moves it (gentlerStart); the first whose columns agree within
// the limits (docs/moving-starts.md, "Consistent columns").
std::optional<Trajectory> consistentStart(const RobotModel& model, const Trajectory& trajectory) {
  const MotionSettings& settings = model.planner.motion;
  const double affordable_s = (1.0 + settings.max_consistency_cost) * trajectory.duration_s();
  for (int i = 1; i <= settings.gentler_start_steps; ++i) {
    Result<Trajectory> gentler = gentlerStart(trajectory, 1.0 - i * settings.gentler_start_step);
    if (gentler && gentler.value().duration_s() > affordable_s) break;
    if (gentler && columnsAgree(settings, gentler.value()) && withinDriveLimits(gentler.value(), model.planner.topp)) {
      return std::move(gentler).value();
    }
  }
  return std::nullopt;
}

}  // namespace

Result<Plan> inconsistentPlan() {
  return Result<Plan>::failure(
      PlanStatus::kColumnsDisagree,
      "the trajectory's velocities or accelerations do not integrate to its positions at 1 ms");
}

bool columnsAgree(const MotionSettings& settings, const Trajectory& trajectory) {
  return columnsAgree(settings, trajectory, settings.consistency_step_s);
}

bool columnsAgree(const MotionSettings& settings, const Trajectory& trajectory, double step_s) {
  const ColumnConsistency c = columnConsistency(trajectory, step_s);
  return c.position_error <= settings.max_position_error && c.velocity_error <= settings.max_velocity_error;
}

std::optional<Trajectory> shortestSlowdown(const RobotModel& model, const Trajectory& trajectory, int steps,
                                           const std::function<bool(const Trajectory&)>& agrees) {
  const MotionSettings& settings = model.planner.motion;
  const double duration = trajectory.duration_s();
  for (int i = 1; i <= steps && duration > 0.0; ++i) {
    Result<Trajectory> slower =
        slowedDown(trajectory, 1.0 + i * settings.slower_step * settings.consistency_step_s / duration);
    if (slower && agrees(slower.value()) && withinDriveLimits(slower.value(), model.planner.topp)) {
      return std::move(slower).value();
    }
  }
  return std::nullopt;
}

Result<Plan> timePaths(const RobotModel& model, const std::vector<PlannedPath>& found, const JointVector& v0) {
  // The spline leaves along v0 with unit speed in the metric Sigma, so sqrt(b_start) = |v0|_Sigma.
  const double speed = weightedNorm(v0, model.planner.metric);
  ToppSolver solver(model.planner.topp);
  Result<Plan> fallback = inconsistentPlan();  // the first trajectory, when no candidate's columns agree
  bool have_fallback = false;
  double topp_ms = 0.0;
  for (size_t i = 0; i < found.size(); ++i) {
    const PlannedPath& path = found[i];
    const auto topp_start = std::chrono::steady_clock::now();
    Plan plan;
    Result<Trajectory> trajectory = solver.solve(path.path, model.driveModel(path.pieces), speed * speed, &plan.solver);
    topp_ms += msSince(topp_start);
    if (!trajectory) {
      if (i == 0) fallback = trajectory.error();
      continue;
    }
    bool agree = columnsAgree(model.planner.motion, trajectory.value());
    plan.method = path.method;
    // From rest, slowing this path by at most two steps costs less than a slower path would.
    if (!agree && speed == 0.0) {
      if (std::optional<Trajectory> slower = consistentSlowdown(model, trajectory.value())) {
        trajectory = std::move(*slower);
        plan.method.repairs |= PlanMethod::kSlowedToAgree;
        agree = true;
      } else if (std::optional<Trajectory> gentler = consistentStart(model, trajectory.value())) {
        trajectory = std::move(*gentler);
        plan.method.repairs |= PlanMethod::kGentlerStart;
        agree = true;
      }
    }
    plan.trajectory = std::make_shared<const Trajectory>(std::move(trajectory).value());
    plan.waypoints = path.waypoints;
    plan.min_clearance_m = path.min_clearance_m;
    plan.times_ms.search = path.search_ms;
    plan.times_ms.smooth = path.smooth_ms;
    plan.times_ms.topp = topp_ms;
    if (agree) return plan;
    if (!have_fallback) {
      fallback = std::move(plan);
      have_fallback = true;
    }
  }
  // None agrees (a moving start's are left to the candidate that stops first): the first.
  if (have_fallback) fallback.value().times_ms.topp = topp_ms;
  return fallback;
}

Result<Plan> timedPath(const RobotModel& model, const PathPlanner& paths, const JointVector& start,
                       const JointVector& goal, HeldPieces pieces, const JointVector& v0,
                       PathAlternatives alternatives) {
  Result<std::vector<PlannedPath>> found = paths.candidates(start, goal, pieces, v0, alternatives);
  if (!found) return found.error();
  return timePaths(model, found.value(), v0);
}

double estimatedSeconds(const RobotModel& model, const Result<std::vector<PlannedPath>>& found, const JointVector& v0) {
  if (!found || found.value().empty()) return std::numeric_limits<double>::infinity();
  const double speed = weightedNorm(v0, model.planner.metric);
  return estimateDuration(*found.value().front().path, model.driveModel(found.value().front().pieces), speed * speed,
                          model.planner.motion.estimate_grid_points);
}

JointVector restOf(const Trajectory& trajectory) { return trajectory.path().at(trajectory.path().length()).q; }

Result<Plan> joinAfter(PlanMethod::Repair first_is, const PlanRequest& request, const Trajectory& first,
                       Result<Plan> onward) {
  if (!onward) return onward;
  Result<Trajectory> joined = joinAtRest(first, *onward.value().trajectory);
  if (!joined) return joined.error();
  Plan plan = std::move(onward).value();
  plan.trajectory = std::make_shared<const Trajectory>(std::move(joined).value());
  plan.waypoints.insert(plan.waypoints.begin(), request.start);
  plan.method.repairs |= first_is;
  return plan;
}

}  // namespace cyber::planner

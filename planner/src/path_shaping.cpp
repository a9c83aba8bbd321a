#include "cyber/planner/path_shaping.hpp"

#include <cmath>
#include <numbers>

#include "cyber/planner/path_clearance.hpp"
#include "cyber/planner/path_timing.hpp"
#include "cyber/planner/weighted_norm.hpp"

namespace cyber::planner {

ShapedPath shapeForTime(std::span<const JointVector> waypoints, int fixed_head, const JointVector& start_velocity,
                        const CollisionWorld& world, const RobotModel& model, double b_start,
                        const ShapeSearchSettings& settings) {
  const std::array<DriveParams, kJointCount> drives{model.elevator_drive, model.arm_drive};
  const JointVector& metric = model.planner.metric;
  const auto n = static_cast<int>(waypoints.size());
  ShapedPath best;
  best.waypoints.assign(waypoints.begin(), waypoints.end());
  auto first = CubicSplinePath::through(best.waypoints, metric, start_velocity);
  if (!first.ok()) return best;
  best.path = std::move(first).value();
  best.estimate_s = estimateDuration(best.path, drives, b_start, settings.grid_points);
  best.min_clearance_m = checkPath(best.path, world, model, model.clearance_m).min_distance_m;
  const int free_first = std::max(1, fixed_head), free_last = n - 2;
  if (free_last < free_first || settings.bumps <= 0 || !std::isfinite(best.estimate_s)) return best;

  // The knots' arc fraction along the starting polygon, and each bump's value there.
  std::vector<double> u(static_cast<size_t>(n), 0.0);
  for (int k = 1; k < n; ++k) {
    u[static_cast<size_t>(k)] =
        u[static_cast<size_t>(k) - 1] +
        weightedNorm(waypoints[static_cast<size_t>(k)] - waypoints[static_cast<size_t>(k) - 1], metric);
  }
  const double total = u.back();
  if (!(total > 0.0)) return best;
  const int bumps = settings.bumps;
  const int parameters = kJointCount * bumps;
  auto bump = [&](int m, int k) { return std::sin((m + 1) * std::numbers::pi * u[static_cast<size_t>(k)] / total); };

  std::vector<JointVector> trial(best.waypoints);
  JointVector step = settings.initial_step;
  const JointVector min_step = settings.min_step_fraction * settings.initial_step;
  std::vector<int> last_sign(static_cast<size_t>(parameters), 1);
  while (best.evaluations < settings.max_evaluations && (step[0] >= min_step[0] || step[1] >= min_step[1])) {
    bool improved = false;
    for (int p = 0; p < parameters && best.evaluations < settings.max_evaluations; ++p) {
      const int joint = p / bumps, m = p % bumps;
      // The direction that helped last time first.
      for (int sign : {last_sign[static_cast<size_t>(p)], -last_sign[static_cast<size_t>(p)]}) {
        if (best.evaluations >= settings.max_evaluations) break;
        trial = best.waypoints;
        bool inside = true;
        for (int k = free_first; k <= free_last; ++k) {
          trial[static_cast<size_t>(k)][joint] += sign * step[joint] * bump(m, k);
          inside = inside && model.withinLimits(trial[static_cast<size_t>(k)]);
        }
        if (!inside) continue;
        ++best.evaluations;
        auto spline = CubicSplinePath::through(trial, metric, start_velocity);
        if (!spline.ok()) continue;
        const double estimate = estimateDuration(spline.value(), drives, b_start, settings.grid_points);
        if (!(estimate < best.estimate_s * (1.0 - 1e-4))) continue;
        const ClearanceCheck check = checkPath(spline.value(), world, model, model.clearance_m);
        if (!check.ok()) continue;
        best.waypoints = trial;
        best.path = std::move(spline).value();
        best.estimate_s = estimate;
        best.min_clearance_m = check.min_distance_m;
        ++best.improvements;
        last_sign[static_cast<size_t>(p)] = sign;
        improved = true;
        break;
      }
    }
    if (!improved) step *= 0.5;
  }
  return best;
}

}  // namespace cyber::planner

#include "path/clearance_escape.hpp"

#include <memory>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "math/weighted_norm.hpp"
#include "path/joined_path.hpp"
#include "path/path_clearance.hpp"

namespace cyber::planner {
namespace {

constexpr double kStartSlack = 1e-9;  // m: the dense check may not go below the start's distance

Result<Trajectory> refuse(std::string reason) {
  return Result<Trajectory>::failure(PlanStatus::kStartInCollision, std::move(reason));
}

}  // namespace

Result<Trajectory> clearanceEscape(const RobotModel& model, const CollisionWorld& world, const JointVector& start,
                                   ToppSolver& solver) {
  const SignedDistance at_start = world.distance(start);
  const double clearance = model.clearance_m;
  if (!(at_start.value > 0.0)) {
    return refuse("it touches an obstacle, so no way out is planned");
  }
  // Steepest ascent of d per unit of Sigma-length: Sigma^-1 grad d, normalised in that norm.
  const JointVector& metric = model.planner.metric;
  const JointVector ascent = at_start.gradient.cwiseQuotient(metric);
  const double ascent_norm = weightedNorm(ascent, metric);
  if (!(ascent_norm > 0.0)) return refuse("the distance to the nearest obstacle has no direction of increase");
  const JointVector direction = ascent / ascent_norm;
  const double slope = at_start.gradient.dot(direction);  // d per unit length, to first order
  const EscapeSettings& settings = model.planner.escape;
  const double target = clearance + settings.margin_m;
  double length = (target - at_start.value) / slope;
  for (int attempt = 0; attempt < settings.length_tries; ++attempt, length *= settings.length_growth) {
    const JointVector end = start + length * direction;
    if (!model.withinLimits(end)) break;
    if (world.distance(end).value < target) continue;
    if (!checkSegment(world, start, end, at_start.value - kStartSlack).clear) {
      return refuse("the way out of the clearance comes closer to the obstacle first");
    }
    auto line = std::make_shared<const StraightPath>(start, direction, length);
    return solver.solve(line, model.driveModel(world.pieces()), 0.0);
  }
  return refuse(
      fmt::format("no straight way out of the clearance within the joint range (distance {:.4f} m)", at_start.value));
}

}  // namespace cyber::planner

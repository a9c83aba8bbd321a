#include "cyber/planner/path_planner.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "cyber/planner/astar_search.hpp"
#include "cyber/planner/path_clearance.hpp"
#include "cyber/planner/path_optimizer.hpp"

namespace cyber::planner {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

double weightedNorm(const JointVector& v, const JointVector& metric) {
  return std::sqrt(metric[kElevator] * v[0] * v[0] + metric[kArm] * v[1] * v[1]);
}

std::string poseText(const JointVector& q) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.4f m, %.4f rad)", q[0], q[1]);
  return buffer;
}

std::string rangeText(const RobotModel& model) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "elevator [%.4f, %.4f] m, arm [%.4f, %.4f] rad", model.elevator_range_m.min,
                model.elevator_range_m.max, model.arm_range_rad.min, model.arm_range_rad.max);
  return buffer;
}

std::string obstacleName(const Scene& scene, int index) {
  // CollisionWorld skips empty polygons; the loader never produces them, so indices agree.
  if (index >= 0 && index < static_cast<int>(scene.obstacles.size())) return scene.obstacles[static_cast<size_t>(index)].name;
  return "an obstacle";
}

constexpr double kSamePose = 1e-9;    // weighted; closer poses are the same pose
constexpr int kMaxConnectionRing = 4; // nodes up to this many steps from a pose may be connected
constexpr int kLeadInHalvings = 5;

// Free grid nodes near a pose that a straight, clear segment reaches, with the connection cost
// |segment|_Sigma (1 + w p(node) / 2) >= |segment|_Sigma (what A*'s heuristic needs). Tries the
// 2 x 2 nodes around the pose first and widens ring by ring.
std::vector<SearchEndpoint> connectToGrid(const CSpaceGrid& grid, const CollisionWorld& world, const JointVector& pose,
                                          double clearance_m) {
  std::vector<SearchEndpoint> out;
  const int corner = grid.lowerCorner(pose);
  const int i0 = grid.elevatorIndex(corner), j0 = grid.armIndex(corner);
  for (int ring = 1; ring <= kMaxConnectionRing && out.empty(); ++ring) {
    for (int i = i0 - ring + 1; i <= i0 + ring; ++i) {
      for (int j = j0 - ring + 1; j <= j0 + ring; ++j) {
        if (i < 0 || j < 0 || i >= grid.elevatorAxis().count || j >= grid.armAxis().count) continue;
        // Only the new ring: the inner nodes were tried already.
        const bool inner = i > i0 - ring + 1 && i < i0 + ring && j > j0 - ring + 1 && j < j0 + ring;
        if (ring > 1 && inner) continue;
        const int cell = grid.cell(i, j);
        if (grid.blocked(cell)) continue;
        if (!checkSegment(world, pose, grid.node(cell), clearance_m).clear) continue;
        const double length = weightedNorm(grid.node(cell) - pose, grid.metric());
        out.push_back({cell, length * (1.0 + 0.5 * grid.potentialWeight() * grid.potential(cell))});
      }
    }
  }
  return out;
}

}  // namespace

PathPlanner::PathPlanner(const RobotModel& model, const Scene& scene) : model_(model), scene_(scene) {
  worlds_.reserve(kPieceSetCount);
  grids_.reserve(kPieceSetCount);
  for (int set = 0; set < kPieceSetCount; ++set) {
    const Clock::time_point t0 = Clock::now();
    worlds_.emplace_back(model_, scene_, HeldPieces::fromIndex(set));
    grids_.push_back(CSpaceGrid::build(worlds_.back(), model_));
    grid_build_ms_[static_cast<size_t>(set)] = millisecondsSince(t0);
  }
}

Result<PlannedPath> PathPlanner::plan(const JointVector& start, const JointVector& goal, HeldPieces pieces,
                                      const JointVector& start_velocity) const {
  using R = Result<PlannedPath>;
  if (!start.allFinite()) return R::failure(PlanStatus::kInvalidInput, "start pose is not a finite number");
  if (!goal.allFinite()) return R::failure(PlanStatus::kInvalidInput, "goal pose is not a finite number");
  if (!start_velocity.allFinite()) return R::failure(PlanStatus::kInvalidInput, "start velocity is not a finite number");
  if (!model_.withinLimits(start)) {
    return R::failure(PlanStatus::kStartOutOfRange, "start " + poseText(start) + " is outside the joint limits: " + rangeText(model_));
  }
  if (!model_.withinLimits(goal)) {
    return R::failure(PlanStatus::kGoalOutOfRange, "goal " + poseText(goal) + " is outside the joint limits: " + rangeText(model_));
  }
  const CollisionWorld& world = worlds_[static_cast<size_t>(pieces.index())];
  const CSpaceGrid& grid = grids_[static_cast<size_t>(pieces.index())];
  const double clearance = model_.clearance_m;
  const JointVector& metric = model_.planner.metric;
  const SmoothingSettings& smoothing = model_.planner.smoothing;
  auto too_close = [&](const char* which, const JointVector& q, const SignedDistance& d) {
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, " is %.4f m from ", d.value);
    char tail[64];
    std::snprintf(tail, sizeof tail, " (clearance %.4f m)", clearance);
    return std::string(which) + " " + poseText(q) + buffer + obstacleName(scene_, d.obstacle) + tail;
  };
  const SignedDistance d_start = world.distance(start);
  if (d_start.value < clearance) return R::failure(PlanStatus::kStartInCollision, too_close("start", start, d_start));
  const SignedDistance d_goal = world.distance(goal);
  if (d_goal.value < clearance) return R::failure(PlanStatus::kGoalInCollision, too_close("goal", goal, d_goal));

  const Clock::time_point t_search = Clock::now();
  PlannedPath out;
  const double start_speed = weightedNorm(start_velocity, metric);
  if (weightedNorm(goal - start, metric) < kSamePose && start_speed == 0.0) {
    const std::vector<JointVector> single{start};
    auto trivial = CubicSplinePath::through(single, metric);
    if (!trivial.ok()) return trivial.error();
    out.path = std::make_shared<const CubicSplinePath>(std::move(trivial).value());
    out.waypoints = out.search_waypoints = single;
    out.min_clearance_m = d_start.value;
    out.direct = true;
    out.method = "zero-length";
    out.search_ms = millisecondsSince(t_search);
    return out;
  }

  // Lead-in: a straight piece along the start velocity, shortened until it is inside the limits
  // and clear (or dropped).
  std::vector<JointVector> polyline{start};
  JointVector from = start;
  if (start_speed > 0.0) {
    const JointVector direction = start_velocity / start_speed;
    double lead = std::min(smoothing.max_lead_in, start_speed * smoothing.lead_in_time_s);
    for (int attempt = 0; attempt <= kLeadInHalvings && lead > kSamePose; ++attempt, lead *= 0.5) {
      const JointVector candidate = start + lead * direction;
      if (model_.withinLimits(candidate) && checkSegment(world, start, candidate, clearance).clear) {
        from = candidate;
        polyline.push_back(candidate);
        out.lead_in = true;
        break;
      }
    }
  }

  if (checkSegment(world, from, goal, clearance).clear) {
    out.direct = true;
    polyline.push_back(goal);
  } else {
    const std::vector<SearchEndpoint> sources = connectToGrid(grid, world, from, clearance);
    if (sources.empty()) {
      return R::failure(PlanStatus::kNoPath, "no free grid node near the start " + poseText(from) +
                                                 " can be reached in a straight line with the clearance");
    }
    const std::vector<SearchEndpoint> goals = connectToGrid(grid, world, goal, clearance);
    if (goals.empty()) {
      return R::failure(PlanStatus::kNoPath, "no free grid node near the goal " + poseText(goal) +
                                                 " can be reached in a straight line with the clearance");
    }
    const auto found = astarSearch(grid, sources, goals, goal);
    if (!found) {
      return R::failure(PlanStatus::kNoPath, "the goal " + poseText(goal) + " cannot be reached from " + poseText(from) +
                                                 " without coming closer than the clearance");
    }
    out.search_expanded = found->expanded;
    for (int cell : found->cells) polyline.push_back(grid.node(cell));
    polyline.push_back(goal);
  }
  out.search_waypoints = polyline;
  out.search_ms = millisecondsSince(t_search);

  // Smoothing: resample, optimise (eq. 8), spline, continuous check; weaker smoothing on failure.
  const Clock::time_point t_smooth = Clock::now();
  const int fixed_head = out.lead_in ? 2 : 1;
  const std::vector<JointVector> tail(polyline.begin() + fixed_head - 1, polyline.end());
  auto prior_at = [&](double spacing) {
    std::vector<JointVector> prior(polyline.begin(), polyline.begin() + fixed_head - 1);
    const std::vector<JointVector> resampled = resamplePolyline(tail, metric, spacing);
    prior.insert(prior.end(), resampled.begin(), resampled.end());
    return prior;
  };
  ClearanceCheck last_check;
  auto accept = [&](const std::vector<JointVector>& waypoints, const char* method) {
    auto spline = CubicSplinePath::through(waypoints, metric, start_velocity);
    if (!spline.ok()) return false;
    last_check = checkPath(spline.value(), world, model_, clearance);
    if (!last_check.ok()) return false;
    out.path = std::make_shared<const CubicSplinePath>(std::move(spline).value());
    out.waypoints = waypoints;
    out.min_clearance_m = last_check.min_distance_m;
    out.method = method;
    return true;
  };
  bool done = false;
  if (out.direct && !out.lead_in) done = accept(polyline, "straight");
  if (!done) {
    const std::vector<JointVector> prior = prior_at(smoothing.waypoint_spacing);
    const SmoothingResult optimised = optimizePath(world, prior, fixed_head, model_, smoothing);
    out.optimizer_iterations = optimised.lbfgs.iterations;
    done = accept(optimised.waypoints, "optimised");
    if (!done) {
      SmoothingSettings stronger = smoothing;
      stronger.obstacle_weight *= 10.0;
      const SmoothingResult pushed = optimizePath(world, prior, fixed_head, model_, stronger);
      out.optimizer_iterations += pushed.lbfgs.iterations;
      done = accept(pushed.waypoints, "optimised, obstacle weight x10");
    }
    if (!done) done = accept(prior, "prior");
    if (!done) done = accept(prior_at(0.25 * smoothing.waypoint_spacing), "dense prior");
  }
  out.smooth_ms = millisecondsSince(t_smooth);
  if (!done) {
    char buffer[200];
    std::snprintf(buffer, sizeof buffer,
                  "no smoothed path keeps the clearance %.4f m and the joint limits (last attempt: %s, %.4f m at s = %.4f)",
                  clearance, last_check.within_limits ? "closest" : "outside the limits", last_check.min_distance_m,
                  last_check.at_s);
    return R::failure(PlanStatus::kClearanceNotMet, buffer);
  }
  return out;
}

}  // namespace cyber::planner

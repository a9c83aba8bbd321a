#include "cyber/planner/motion_planner.hpp"

#include <chrono>
#include <cmath>
#include <string>

namespace cyber::planner {
namespace {

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
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
  Result<PlannedPath> path = paths.plan(request.start, request.goal, request.pieces, request.start_velocity);
  if (!path) return path.error();

  // The spline leaves along v0 with unit speed in the metric Sigma, so sqrt(b_start) = |v0|_Sigma.
  const JointVector& metric = model_.planner.metric;
  const double b_start = request.start_velocity.dot(metric.cwiseProduct(request.start_velocity));

  const auto topp_start = std::chrono::steady_clock::now();
  Plan plan;
  ToppSolver solver(model_.planner.topp);
  Result<Trajectory> trajectory =
      solver.solve(path.value().path, model_.elevator_drive, model_.arm_drive, b_start, &plan.solver);
  plan.times_ms.topp = msSince(topp_start);
  if (!trajectory) return trajectory.error();

  plan.trajectory = std::make_shared<const Trajectory>(std::move(trajectory).value());
  plan.waypoints = path.value().waypoints;
  plan.min_clearance_m = path.value().min_clearance_m;
  plan.path_method = path.value().method;
  plan.times_ms.grid = paths.gridBuildMs(request.pieces);
  plan.times_ms.search = path.value().search_ms;
  plan.times_ms.smooth = path.value().smooth_ms;
  plan.times_ms.total = msSince(start_time);
  return plan;
}

}  // namespace cyber::planner

#include "cyber/daemon/motion_planner_service.hpp"

#include <algorithm>
#include <chrono>
#include <optional>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/fastest_stop.hpp"
#include "cyber/planner/motion_planner.hpp"

namespace cyber::daemon {

namespace {

class TrajectorySource final : public SetpointSource {
 public:
  explicit TrajectorySource(std::shared_ptr<const planner::Trajectory> trajectory)
      : trajectory_(std::move(trajectory)) {}
  [[nodiscard]] double durationS() const override { return trajectory_->duration_s(); }
  [[nodiscard]] JointSetpoints at(double t_s) const override {
    const planner::TrajectorySample sample = trajectory_->sample(t_s);
    JointSetpoints out;
    out.position = sample.q;
    out.velocity = sample.qdot;
    // The optimiser holds each voltage to its limit within its tolerance between grid points
    // (docs/algorithm.md section 3, "Stopping rules"), so a sample may ask for a few millivolts
    // more; a motor controller gives the drive no more than its limit, and neither does the stream.
    for (int j = 0; j < planner::kJointCount; ++j) {
      const double limit = trajectory_->drive(j).voltage_limit_volts;
      out.volts[j] = std::clamp(sample.volts[j], -limit, limit);
    }
    return out;
  }

 private:
  std::shared_ptr<const planner::Trajectory> trajectory_;
};

class MotionPlannerService final : public PlanningService {
 public:
  explicit MotionPlannerService(planner::MotionPlanner planner) : planner_(std::move(planner)) {}

  [[nodiscard]] planner::Result<PlannedMotion> plan(const MotionRequest& request) const override {
    if (request.kind == MotionKind::kStop) return stop(request);
    planner::PlanRequest plan_request;
    plan_request.start = request.start;
    plan_request.goal = request.goal;
    plan_request.start_velocity = request.start_velocity;
    plan_request.pieces = request.pieces;
    plan_request.scene = request.scene;
    plan_request.scene_offset_m = request.scene_offset_m;
    auto plan = planner_.plan(plan_request);
    if (!plan) return plan.error();
    const planner::Plan& value = plan.value();
    PlannedMotion out;
    out.trajectory = std::make_shared<TrajectorySource>(value.trajectory);
    out.times_ms = value.times_ms;
    out.min_clearance_m = value.min_clearance_m;
    return out;
  }

 private:
  // ARM_CANCEL's hold: the planner's fastest stop along the start velocity, in the collision world
  // of the motion it brakes (docs/lcm.md, "Cancel and manual override").
  [[nodiscard]] planner::Result<PlannedMotion> stop(const MotionRequest& request) const {
    const planner::RobotModel& model = planner_.model();
    if (request.scene < 0 || request.scene >= static_cast<int>(model.scenes.size())) {
      return planner::Result<PlannedMotion>::failure(planner::PlanStatus::kInvalidInput,
                                                     "unknown scene index " + std::to_string(request.scene));
    }
    const auto started = std::chrono::steady_clock::now();
    planner::ToppSolver solver(model.planner.topp);
    // The world the braked motion was planned in: the scene as drawn, or shifted by its offset.
    const planner::PathPlanner& drawn = planner_.pathPlanner(request.scene);
    std::optional<planner::CollisionWorld> shifted;
    if (request.scene_offset_m != 0.0) {
      shifted.emplace(model, drawn.scene(), request.pieces, request.scene_offset_m);
    }
    auto stop = planner::fastestStop(model, shifted ? *shifted : drawn.world(request.pieces), request.start,
                                     request.start_velocity, solver);
    if (!stop) return stop.error();
    PlannedMotion out;
    out.trajectory =
        std::make_shared<TrajectorySource>(std::make_shared<const planner::Trajectory>(std::move(stop).value()));
    out.times_ms.topp = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    out.times_ms.total = out.times_ms.topp;
    return out;
  }

  planner::MotionPlanner planner_;
};

}  // namespace

planner::Result<std::unique_ptr<PlanningService>> makeMotionPlannerService(const planner::RobotModel& robot) {
  auto planner = planner::MotionPlanner::create(robot);
  if (!planner) return planner.error();
  return std::unique_ptr<PlanningService>(std::make_unique<MotionPlannerService>(std::move(planner).value()));
}

}  // namespace cyber::daemon

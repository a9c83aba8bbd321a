#include "cyber/daemon/motion_planner_service.hpp"

#include <algorithm>
#include <memory>
#include <utility>

#include "cyber/planner.hpp"

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
    out.volts = sample.volts;
    for (int j = 0; j < sample.volts.size(); ++j) {
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

  // A goal: the plan from the start; ARM_CANCEL's hold: the planner's fastest stop along the start
  // velocity, in the collision world of the motion it brakes (docs/lcm.md, "Cancel and manual
  // override").
  [[nodiscard]] planner::Result<PlannedMotion> plan(const MotionRequest& request) const override {
    planner::PlanRequest plan_request;
    plan_request.start = request.start;
    plan_request.goal = request.goal;
    plan_request.start_velocity = request.start_velocity;
    plan_request.pieces = request.pieces;
    plan_request.scene = request.scene;
    plan_request.scene_offset_m = request.scene_offset_m;
    auto plan = request.kind == MotionKind::kStop ? planner_.stop(plan_request) : planner_.plan(plan_request);
    if (!plan) return plan.error();
    const planner::Plan& value = plan.value();
    PlannedMotion out;
    out.trajectory = std::make_shared<TrajectorySource>(value.trajectory);
    out.times_ms = value.times_ms;
    out.min_clearance_m = value.min_clearance_m;
    return out;
  }

 private:
  planner::MotionPlanner planner_;
};

}  // namespace

planner::Result<std::unique_ptr<PlanningService>> makeMotionPlannerService(
    const planner::RobotModel& robot, const std::optional<std::filesystem::path>& cache_dir) {
  auto planner = planner::MotionPlanner::create(robot, planner::GridSelection{}, cache_dir);
  if (!planner) return planner.error();
  return std::unique_ptr<PlanningService>(std::make_unique<MotionPlannerService>(std::move(planner).value()));
}

}  // namespace cyber::daemon

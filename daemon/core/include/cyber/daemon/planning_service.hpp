#pragma once
// The seam between the daemon and the planner: one blocking call per plan, made on the worker
// thread. makeMotionPlannerService (motion_planner_service.hpp) wraps planner::MotionPlanner; tests use fakes.

#include "cyber/daemon/setpoint_source.hpp"
#include "cyber/planner.hpp"

namespace cyber::daemon {

enum class MotionKind {
  kMove,  // start to goal, collision-free, ending at rest
  kStop,  // ARM_CANCEL's hold: the fastest admissible stop from (start, start_velocity); goal unused
};

struct MotionRequest {
  MotionKind kind = MotionKind::kMove;
  JointVector start;
  JointVector goal;
  JointVector start_velocity;  // non-zero for a splice into a running motion
  planner::HeldPieces pieces;
  int scene = 0;
  double scene_offset_m = 0.0;  // the scene's field elements shifted in x (planner::PlanRequest)
};

using StageTimesMs = planner::StageTimesMs;

struct PlannedMotion {
  SharedSetpointSource trajectory;
  StageTimesMs times_ms;
  double min_clearance_m = 0.0;
};

class PlanningService {
 public:
  virtual ~PlanningService() = default;
  // Thread-safe; called from the planning worker only.
  [[nodiscard]] virtual planner::Result<PlannedMotion> plan(const MotionRequest& request) const = 0;
};

}  // namespace cyber::daemon

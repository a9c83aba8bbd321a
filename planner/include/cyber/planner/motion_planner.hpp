#pragma once
// The planner's front door: a request in, a time-optimal collision-free trajectory out.
// Chains the path stage (algorithm.md section 2) and TOPP (section 3). Built once per robot:
// the grids of every scene and game-piece set are made in create(), never per request.
// plan() is const and keeps no state between calls, so several threads may share one planner.

#include <memory>
#include <optional>
#include <vector>

#include "cyber/planner/path_planner.hpp"
#include "cyber/planner/result.hpp"
#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/stage_times.hpp"
#include "cyber/planner/topp.hpp"
#include "cyber/planner/trajectory.hpp"

namespace cyber::planner {

struct PlanRequest {
  JointVector start = JointVector::Zero();           // (m, rad)
  JointVector goal = JointVector::Zero();            // (m, rad)
  JointVector start_velocity = JointVector::Zero();  // (m/s, rad/s); zero: start at rest
  HeldPieces pieces;
  int scene = 0;  // index into RobotModel::scenes
  // Shift of the scene's field elements in x (> 0: the robot further from them), within the
  // scene's offset_range_m (docs/algorithm.md section 2, "Scene offsets").
  double scene_offset_m = 0.0;
};

using SolverReport = ToppReport;

struct Plan {
  std::shared_ptr<const Trajectory> trajectory;
  std::vector<JointVector> waypoints;  // the spline's knots, exact start to exact goal
  StageTimesMs times_ms;
  SolverReport solver;
  double min_clearance_m = 0.0;  // smallest distance to an obstacle found along the path
  std::string path_method;       // which path attempt succeeded (see PlannedPath::method)
};

// Which grids create() builds: every one (the daemon, which must answer any goal without
// building one), or only those one move needs (cyber-plan, whose start-up is most of its run).
struct GridSelection {
  int scene = -1;                        // -1: every scene
  std::optional<double> scene_offset_m;  // set: only the grids of this offset; unset: every band
};

class MotionPlanner {
 public:
  // Builds the path planners (and grids) of every scene. Fails with kInvalidInput when the model
  // has no scene or no arm geometry.
  static Result<MotionPlanner> create(const RobotModel& model, const GridSelection& selection = GridSelection{});

  [[nodiscard]] Result<Plan> plan(const PlanRequest& request) const;

  [[nodiscard]] const RobotModel& model() const { return model_; }
  // The path stage of a scene as drawn (offset 0; built unless a GridSelection left it out).
  [[nodiscard]] const PathPlanner& pathPlanner(int scene) const {
    return path_planners_[static_cast<size_t>(scene)].front();
  }
  // The bands of scene offsets a scene's grids were built for (the first is the offset 0 alone).
  [[nodiscard]] std::vector<JointRange> offsetBands(int scene) const;

 private:
  MotionPlanner() = default;
  RobotModel model_;
  // By scene index: the scene as drawn, then one planner per band of offsets.
  std::vector<std::vector<PathPlanner>> path_planners_;
};

}  // namespace cyber::planner

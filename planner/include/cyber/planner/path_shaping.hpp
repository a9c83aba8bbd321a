#pragma once
// Shape search of a candidate path against its reachability time (docs/performance.md,
// "Choosing the path for time"): the spline's free knots are displaced by a few smooth bumps per
// joint (sin(m pi u) over the knots' arc fraction u, zero at both ends), and a compass search over
// the bumps' amplitudes keeps every step that lowers estimateDuration and whose spline passes
// the continuous clearance check and stays inside the joint limits. The search, its smoothing
// toward the A* prior and the potential make paths that keep to the middle of the free space;
// this lets the time itself pull the path toward the obstacles where that is faster.

#include <array>
#include <span>
#include <vector>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/cubic_spline_path.hpp"
#include "cyber/planner/robot_model.hpp"

namespace cyber::planner {

struct ShapeSearchSettings {
  int bumps = 2;                         // per joint
  int max_evaluations = 16;              // spline + reachability estimates
  int grid_points = 40;                  // of each estimate
  JointVector initial_step{0.03, 0.09};  // amplitude steps [m, rad]; about 10 ms of top speed each
  double min_step_fraction = 0.125;      // stop when the steps have shrunk to this share
};

struct ShapedPath {
  std::vector<JointVector> waypoints;  // the shaped knots (the input's when nothing was better)
  CubicSplinePath path;
  double estimate_s = 0.0;
  double min_clearance_m = 0.0;
  int evaluations = 0;
  int improvements = 0;  // accepted steps; 0: the input is returned unchanged
};

// Starts from `waypoints` (their spline must already be clear); the first fixed_head knots and the
// last stay where they are. b_start and the drives as for estimateDuration.
ShapedPath shapeForTime(std::span<const JointVector> waypoints, int fixed_head, const JointVector& start_velocity,
                        const CollisionWorld& world, const RobotModel& model, double b_start,
                        const ShapeSearchSettings& settings);

}  // namespace cyber::planner

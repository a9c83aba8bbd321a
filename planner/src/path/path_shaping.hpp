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
#include "cyber/planner/robot_model.hpp"
#include "path/cubic_spline_path.hpp"

namespace cyber::planner {

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

// A second, longer search for the candidates still far above their slower joint alone
// (docs/performance.md, "Choosing the path for time"): more bumps, and each amplitude keeps its own
// step, doubled when it helped and halved when neither sign did, so the evaluations go where
// they gain. A step that is faster but loses the clearance somewhere is tried once more with a
// window that holds the knots still there: the fastest paths touch the clearance, and a bump
// over the whole path would otherwise push that place into the obstacle every time.
// As shapeForTime, with the refinement's steps and held windows. Returns the input unchanged when
// it has fewer than two free knots per bump (the bumps would not be independent over so few).
ShapedPath refineShapeForTime(std::span<const JointVector> waypoints, int fixed_head, const JointVector& start_velocity,
                              const CollisionWorld& world, const RobotModel& model, double b_start,
                              const ShapeRefinementSettings& settings);

}  // namespace cyber::planner

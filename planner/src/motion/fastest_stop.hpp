#pragma once
// The fastest admissible stop of a moving mechanism along its current velocity
// (docs/moving-starts.md): a straight path along v0, just long enough to brake to rest within
// the drive limits and the joint range, with clearance kept along it.

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/trajectory.hpp"
#include "cyber/planner/types.hpp"
#include "timing/topp.hpp"

namespace cyber::planner {

// start with velocity v0 != 0 to rest on the StraightPath along v0. Errors: kInvalidInput (v0
// zero or not finite), kInfeasibleStart (no stop before a joint limit), kClearanceNotMet (the
// braking segment comes closer than the clearance), and the solver's errors.
Result<Trajectory> fastestStop(const RobotModel& model, const CollisionWorld& world, const JointVector& start,
                               const JointVector& velocity, ToppSolver& solver);

}  // namespace cyber::planner

namespace cyber::planner {

// The same stop made slower by braking `factor` (>= 1) times more gently along a line `factor`
// times as long: b(s) becomes b(s / factor), so every deceleration shrinks by 1 / factor (between
// coasting and the fastest stop, so still inside the limits) and the duration grows by factor.
// kClearanceNotMet or kInfeasibleStart when the longer line leaves the clearance or the range.
Result<Trajectory> stretchedStop(const RobotModel& model, const CollisionWorld& world, const Trajectory& stop,
                                 double factor);

}  // namespace cyber::planner

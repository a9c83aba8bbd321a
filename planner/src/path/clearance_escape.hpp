#pragma once
// Leaving a start at rest that is inside the clearance but touches nothing (docs/algorithm.md
// section 5): after an outage, or a push, the mechanism can come to rest nearer an obstacle than
// the clearance, and refusing every goal from there would leave it stuck.

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/trajectory.hpp"
#include "cyber/planner/types.hpp"
#include "timing/topp.hpp"

namespace cyber::planner {

// From `start` at rest with 0 < d(start) < clearance: the straight line along which the distance
// grows fastest in the metric Sigma, just long enough to end EscapeSettings::margin_m beyond the clearance,
// never closer than the start at any dense sample, timed from rest to rest. kStartInCollision
// (with the reason) when the start touches or overlaps an obstacle, or no such line exists within
// the joint range; the solver's errors otherwise.
Result<Trajectory> clearanceEscape(const RobotModel& model, const CollisionWorld& world, const JointVector& start,
                                   ToppSolver& solver);

}  // namespace cyber::planner

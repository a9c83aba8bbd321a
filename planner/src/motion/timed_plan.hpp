#pragma once
// From candidate paths to a timed Plan: TOPP along each candidate in the order of its estimate,
// the 1 ms column check every plan must pass (docs/moving-starts.md, "Consistent columns"), and
// the joins that put a stop or a way out of the clearance before a rest-to-rest plan. Shared by
// the plan from rest (MotionPlanner::plan) and the moving-start strategies
// (moving_start_strategies.hpp).

#include <functional>
#include <optional>
#include <vector>

#include "cyber/planner/motion_planner.hpp"
#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/trajectory.hpp"
#include "path/path_planner.hpp"

namespace cyber::planner {

// The failure of a plan whose columns disagree at 1 ms (also "not timed yet").
Result<Plan> inconsistentPlan();

// The shortest uniform slowdown of `trajectory` by a multiple of MotionSettings::slower_step, up to
// `steps` of them, that stays within the limits and that `agrees` accepts.
std::optional<Trajectory> shortestSlowdown(const RobotModel& model, const Trajectory& trajectory, int steps,
                                           const std::function<bool(const Trajectory&)>& agrees);

// TOPP along `found` from a start with velocity v0, in their order, until one gives a trajectory
// whose columns agree (from rest slowed or started more gently when that makes them agree); the
// first trajectory when none does.
Result<Plan> timePaths(const RobotModel& model, const std::vector<PlannedPath>& found, const JointVector& v0);

// The path stage from `start` leaving along v0, then timePaths.
Result<Plan> timedPath(const RobotModel& model, const PathPlanner& paths, const JointVector& start,
                       const JointVector& goal, HeldPieces pieces, const JointVector& v0,
                       PathAlternatives alternatives = PathAlternatives::kSearch);

// The reachability pass's estimate of the first candidate's duration (path_timing.hpp), infinity
// when there is none.
double estimatedSeconds(const RobotModel& model, const Result<std::vector<PlannedPath>>& found, const JointVector& v0);

// Where a trajectory ends.
JointVector restOf(const Trajectory& trajectory);

// `first` (a stop, or a way out of the clearance: which one, `first_is`), then the rest-to-rest
// plan `onward` from where it ends.
Result<Plan> joinAfter(PlanMethod::Repair first_is, const PlanRequest& request, const Trajectory& first,
                       Result<Plan> onward);

}  // namespace cyber::planner

#pragma once
// A candidate path drawn by the joints' own fastest motions (docs/algorithm.md section 2.5).
// Many rest-to-rest moves are as fast as their slower joint moving
// alone: that joint runs its own time-optimal profile and the faster one fits in beside it. The
// search's paths keep to the middle of the free space and lose 3-5 % on such moves. So the
// slower joint's profile, stretched by a few factors, is paired with the faster joint's profile
// delayed and stretched to fit inside it; the pairs whose spline through samples at even times
// keeps the clearance are timed by the reachability pass, and the first within a few per cent
// of its own construction's time (or the fastest of a few) is returned.

#include <array>
#include <optional>
#include <vector>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/robot_model.hpp"
#include "path/cubic_spline_path.hpp"

namespace cyber::planner {

struct SynchronisedPath {
  std::vector<JointVector> waypoints;
  CubicSplinePath path;
  double estimate_s = 0.0;      // on estimate_points
  double slower_alone_s = 0.0;  // the slower joint's own time-optimal duration
  double min_clearance_m = 0.0;
};

// Rest to rest from `from` to `to`; nothing when a joint does not move, when the slower joint alone
// cannot beat `beat_s` (the fastest candidate's estimate so far) or when no pair keeps the clearance.
std::optional<SynchronisedPath> synchronisedPath(const JointVector& from, const JointVector& to,
                                                 const CollisionWorld& world, const RobotModel& model, double beat_s,
                                                 const SynchronisedSettings& settings = {});

}  // namespace cyber::planner

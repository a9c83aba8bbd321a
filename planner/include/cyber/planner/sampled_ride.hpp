#pragma once
// The fastest ride along a trajectory's path as a check that reads only its samples sees it (an
// external referee's along-path ratio, docs/moving-starts.md, "The CSV's spacing"): independent of
// the planner's TOPP, sharing only the drive model's voltages and currents. Where the path's
// tangent in its own time goes to zero (a turn, the end at rest) samples far apart let the ride
// pass faster than any motor could; the gain shrinks with the spacing.

#include <optional>
#include <span>

#include "cyber/planner/trajectory.hpp"

namespace cyber::planner {

// The shortest time in which the path q(s) of `trajectory`, s its own time, read at the increasing
// times `times_s` (the first 0, the last its duration), can be traversed within its drives'
// limits: each sample's voltage, current and optional velocity and acceleration limits bound the
// path acceleration s'' to an interval at each path speed squared b = s'^2; a backward pass finds
// the largest b from which the end is still reachable, a greedy forward pass rides at the upper
// bound (reachability analysis, docs/algorithm.md section 3). A moving start keeps its speed
// (b = 1 at s = 0); the ride ends at rest. nullopt when these samples admit no ride.
[[nodiscard]] std::optional<double> fastestRideAlongSamples(const Trajectory& trajectory,
                                                            std::span<const double> times_s);

// The same on samples evenly about `step_s` apart, the last at the end.
[[nodiscard]] std::optional<double> fastestRideAlongPath(const Trajectory& trajectory, double step_s);

}  // namespace cyber::planner

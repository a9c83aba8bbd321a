#pragma once
// The fastest ride along a trajectory's own path, as an external referee judges a CSV's along-path
// ratio (docs/performance.md, "Seeded random moves on the three robots"): independent of the
// planner's TOPP, sharing only the drive model's voltages and currents.

#include <optional>

#include "cyber/planner/trajectory.hpp"

namespace cyber::test {

// The shortest time in which the path q(s) of `trajectory`, with s its own time sampled about
// `step_s` apart (evenly, the last sample at its end), can be traversed within its drives' limits:
// each sample's voltage, current and optional velocity and acceleration limits bound the path
// acceleration s'' to an interval at each path speed squared b = s'^2; a backward pass finds the
// largest b from which the end is still reachable, a greedy forward pass rides at the upper
// bound (reachability analysis, docs/algorithm.md section 3). A moving start keeps its speed
// (b = 1 at s = 0); the ride ends at rest. nullopt when these samples admit no ride.
[[nodiscard]] std::optional<double> fastestRideAlongPath(const planner::Trajectory& trajectory, double step_s);

}  // namespace cyber::test

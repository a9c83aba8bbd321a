#pragma once
// A quick estimate of how long a path takes (algorithm.md section 3's warm start alone): the
// forward-backward reachability profile on a coarse grid, used to choose between candidate paths
// before the full time-optimal parameterisation of the chosen one.

#include <array>
#include <vector>

#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

// Seconds from path speed^2 b_start (path units) to rest at the end; infinity when the profile
// does not exist (a limit that cannot hold, a start that cannot be stopped).
double estimateDuration(const GeometricPath& path, const DriveModel& drives, double b_start, int grid_points);

// The same profile's times: at each grid point, the fraction of the path's length reached and the
// seconds it took (both start at 0; the last fraction is 1 and the last time estimateDuration).
// Empty when the profile does not exist; a single point (0, 0) for a path of length 0.
struct TimedFractions {
  std::vector<double> fraction;
  std::vector<double> time_s;
};
TimedFractions reachabilityTimes(const GeometricPath& path, const DriveModel& drives, double b_start, int grid_points);

}  // namespace cyber::planner

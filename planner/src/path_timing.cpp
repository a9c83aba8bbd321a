#include "cyber/planner/path_timing.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "cyber/planner/topp_problem.hpp"
#include "cyber/planner/topp_reachability.hpp"

namespace cyber::planner {

double estimateDuration(const GeometricPath& path, const std::array<DriveParams, kJointCount>& drives, double b_start,
                        int grid_points) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  const double length = path.length();
  if (!(length > 0.0)) return 0.0;
  topp::Problem problem;
  topp::sampleGrid(path, grid_points, problem);
  topp::LimitMargins margins;
  margins.reset(problem.intervals());
  std::string error;
  if (!topp::buildRows(drives, margins, problem, &error)) return kNever;
  problem.b_start = b_start / (length * length);
  problem.b_end = 0.0;
  problem.speed_bound = 1e3 / length;
  std::vector<double> b, controllable;
  if (topp::forwardBackward(problem, b, controllable).status != topp::ReachabilityStatus::kOk) return kNever;
  double t = 0.0;  // in units of the unit-length path: b is (ds/dt)^2 / length^2
  for (int k = 0; k < problem.intervals(); ++k) {
    const double speed_sum = std::sqrt(b[static_cast<size_t>(k)]) + std::sqrt(b[static_cast<size_t>(k) + 1]);
    if (!(speed_sum > 0.0)) return kNever;
    t += 2.0 * problem.ds(k) / speed_sum;
  }
  return t;
}

}  // namespace cyber::planner

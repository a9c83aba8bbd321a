#include "timing/path_timing.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "timing/topp_problem.hpp"
#include "timing/topp_reachability.hpp"

namespace cyber::planner {
namespace {

// An estimate compares candidate paths, and a C_k short by this much costs far less time than the
// differences it decides (the TOPP itself bisects to topp::Problem's default).
constexpr double kEstimateControllableTolerance = 1e-3;

}  // namespace

TimedFractions reachabilityTimes(const GeometricPath& path, const DriveModel& drives, double b_start, int grid_points) {
  TimedFractions out;
  const double length = path.length();
  if (!(length > 0.0)) {
    out.fraction.assign(1, 0.0);
    out.time_s.assign(1, 0.0);
    return out;
  }
  topp::Problem problem;
  topp::sampleGrid(path, grid_points, problem);
  topp::LimitMargins margins;
  margins.reset(problem.intervals());
  if (!topp::buildRows(drives, margins, problem)) return out;
  problem.b_start = b_start / (length * length);
  problem.b_end = 0.0;
  problem.speed_bound = topp::unitSpeedBound(length);
  problem.controllable_tolerance = kEstimateControllableTolerance;
  std::vector<double> b, controllable;
  if (topp::forwardBackward(problem, b, controllable).status != topp::ReachabilityStatus::kOk) return out;
  out.fraction = problem.s;
  out.time_s.assign(problem.s.size(), 0.0);
  double t = 0.0;  // in units of the unit-length path: b is (ds/dt)^2 / length^2
  for (int k = 0; k < problem.intervals(); ++k) {
    const double speed_sum = std::sqrt(b[static_cast<size_t>(k)]) + std::sqrt(b[static_cast<size_t>(k) + 1]);
    if (!(speed_sum > 0.0)) return TimedFractions{};
    t += 2.0 * problem.ds(k) / speed_sum;
    out.time_s[static_cast<size_t>(k) + 1] = t;
  }
  return out;
}

double estimateDuration(const GeometricPath& path, const DriveModel& drives, double b_start, int grid_points) {
  const TimedFractions times = reachabilityTimes(path, drives, b_start, grid_points);
  return times.time_s.empty() ? std::numeric_limits<double>::infinity() : times.time_s.back();
}

}  // namespace cyber::planner

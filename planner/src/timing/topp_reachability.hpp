#pragma once
// Forward-backward reachability pass (algorithm.md section 3, the classical warm start) over the
// SAME rows as the optimiser: each interval k carries one constant a_k = (c_{k+1}^2 - c_k^2)/(2 ds)
// and its rows sit at both ends, so every row is a quadratic in the unknown speed c of one end
// once the other end's speed is fixed; the largest admissible speed is the root or bound where
// all rows hold. The backward pass gives the controllable set [0, C_k] (speeds^2 from which the
// goal can still be reached at rest), the forward pass the greedy fastest profile inside it.
// Deterministic; a few hundred flops per interval (plus a bisection where braking binds).

#include <string>
#include <vector>

#include "timing/topp_problem.hpp"

namespace cyber::planner::topp {

struct AccelInterval {
  double lo;
  double hi;
  [[nodiscard]] bool empty() const { return lo > hi; }
};

// The a admitted on `interval` with b at its left node, by the rows at that node only (an outer
// bound: the rows further along the interval can only narrow it).
AccelInterval admissibleAcceleration(const Problem& problem, int interval, double b);

// Largest speed c_{k+1} in [0, c_next_max] such that every row of interval k holds with
// c_k = c_now; negative when there is none.
double fastestNextSpeed(const Problem& problem, int interval, double c_now, double c_next_max);

enum class ReachabilityStatus { kOk, kStartNotControllable, kNotControllable };

struct ReachabilityResult {
  ReachabilityStatus status = ReachabilityStatus::kOk;
  std::string reason;
  double controllable_start_b = 0.0;  // C_0: the largest b_start that can still be stopped
  double start_b = 0.0;               // b[0]: problem.b_start, or C_0 when it was above C_0 within the tolerance
};

// Fills b (K values) with the greedy profile from problem.b_start to problem.b_end.
// `controllable` is a caller-owned buffer (resized to K). A start up to (1 + start_speed_tolerance)
// times faster than sqrt(C_0) starts from C_0 instead of failing: the solver's own trajectories may
// overshoot a limit by its check tolerance, so a splice taken from one of them can sit just past
// the controllable set of the new path.
ReachabilityResult forwardBackward(const Problem& problem, std::vector<double>& b, std::vector<double>& controllable,
                                   double start_speed_tolerance = 0.0);

}  // namespace cyber::planner::topp

#pragma once
// Path optimisation of algorithm.md section 2.3 (report eq. 8): with the search waypoints xbar as
// a prior, minimise over the free waypoints
//
//   J = sum_i sum_pairs w_o phi(d_pair(x_i)) + sum w_p |x_i - xbar_i|^2_S + sum w_l |x_{i+1} - x_i|^2_S
//       + sum w_s |x_{i-1} - 2 x_i + x_{i+1}|^2_S + sum w_lim (joint-limit excess)^2
//
// Two deliberate departures from the letter of eq. 8, both measured on the public moves:
//  - The obstacle term sums phi over every robot-polygon x obstacle pair near x_i instead of
//    taking phi of the minimum d(x_i). With one close pair the two agree; where the closest pair
//    switches, min() has a kink on which L-BFGS crawled (often > 200 iterations), while the sum is
//    smooth (~25 iterations to a gradient 1e-4).
//  - phi(d) = exp(-d/d0)^2, shifted and tilted to reach 0 with zero slope at
//    d = kObstacleCutoffDecays * d0 (it differs from exp(-2 d/d0) by < 1e-4 w_o), so pairs farther
//    away need no exact distance, which keeps the evaluation cheap.
// The limit term keeps the waypoints GridSettings::joint_limit_margin inside the joint box (eq. 8 itself knows
// no limits); it is soft and what it leaves is clamped.
//
// The minimiser is the shared L-BFGS with the Lewis-Overton line search. The quadratic part of J
// is badly conditioned (the smoothness term is a fourth difference), so the variables are
// preconditioned by its exact banded Cholesky factor: x = xbar + L^-T y with L L^T = Hessian of
// the quadratic part, making that part the identity in y.

#include <vector>

#include <Eigen/Core>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/robot_model.hpp"
#include "math/banded_cholesky.hpp"
#include "math/lbfgs.hpp"
#include "path/cspace_grid.hpp"

namespace cyber::planner {

// phi's cutoff in decay lengths: exp(-12) leaves under 1e-5 of w_o beyond it (see above).
inline constexpr double kObstacleCutoffDecays = 6.0;

// J of eq. 8 over the free waypoints: indices fixed_head .. N-2 of the prior (the first fixed_head
// waypoints and the last are fixed). Variables are joint-major: [t of each free waypoint, then
// theta of each].
class SmoothingObjective {
 public:
  SmoothingObjective(const CollisionWorld& world, std::vector<JointVector> prior, int fixed_head,
                     const RobotModel& model, const SmoothingSettings& settings);

  [[nodiscard]] int freeCount() const { return free_count_; }
  [[nodiscard]] Eigen::VectorXd priorVariables() const;
  [[nodiscard]] std::vector<JointVector> waypoints(const Eigen::VectorXd& x) const;
  // Cost and gradient (gradient sized like x).
  double evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const;
  // Hessian of the quadratic terms (prior, length, smoothness) for one joint over the free
  // waypoints: pentadiagonal (lower bandwidth 2), unfactored.
  void quadraticHessian(int joint, BandedCholesky& hessian) const;

 private:
  const CollisionWorld& world_;
  std::vector<JointVector> prior_;
  int fixed_head_;
  int free_count_;
  JointVector metric_;
  SmoothingSettings settings_;
  [[nodiscard]] int jointCount() const { return limits_.size(); }
  // Free waypoint k's joint values: variable k of each joint's block of freeCount().
  [[nodiscard]] JointVector variablesOf(const Eigen::VectorXd& x, int k) const {
    JointVector q(jointCount());
    for (int j = 0; j < jointCount(); ++j) q[j] = x[j * free_count_ + k];
    return q;
  }

  PerJoint<JointRange> limits_;
  double limit_margin_;                      // GridSettings::joint_limit_margin
  mutable std::vector<JointVector> points_;  // scratch: the whole waypoint list at x
};

struct SmoothingResult {
  std::vector<JointVector> waypoints;  // fixed ends unchanged, free waypoints inside the limits
  LbfgsResult lbfgs{LbfgsStatus::kConverged, 0, 0, 0.0, 0.0};
};

// Minimises J from the prior. With no free waypoint returns the prior unchanged.
SmoothingResult optimizePath(const CollisionWorld& world, const std::vector<JointVector>& prior, int fixed_head,
                             const RobotModel& model, const SmoothingSettings& settings);

// Points at equal weighted arc length along a polyline, spacing <= max_spacing, both ends exact.
std::vector<JointVector> resamplePolyline(const std::vector<JointVector>& polyline, const JointVector& metric,
                                          double max_spacing);

}  // namespace cyber::planner

#pragma once
// The second-order cone program of algorithm.md section 3 and its augmented Lagrangian solver
// (eqs. 19-23, 30-32) with L-BFGS inner minimisations.
//
//   minimise    sum_k 2 ds_k d_k
//   subject to  (c_k + c_{k+1} + d_k, c_k + c_{k+1} - d_k, 2) in Q3    (time cones, k < K-1)
//               (b_k + 1, b_k - 1, 2 c_k) in Q3                          (speed cones)
//               c_k^2 - b_k = 0                                          (eqs. 28-29)
//               b_{k+1} - b_k - 2 ds_k a_k = 0, b_0 = b_start, b_{K-1} = b_end,
//               c_0 = sqrt(b_start), c_{K-1} = sqrt(b_end)
//               lo <= alpha a_k + beta b_n + gamma c_n <= hi  (every limit row), -b_k <= 0
//
// Every evaluation of L_rho and its gradient walks each constraint once: O(K) time and memory.

#include <array>

#include <Eigen/Core>

#include "cyber/planner/planner_settings.hpp"
#include "math/banded_cholesky.hpp"
#include "math/lbfgs.hpp"
#include "timing/topp_problem.hpp"

namespace cyber::planner::topp {

// x interleaved by node, [a_k, b_k, c_k, d_k] for k < K-1 and [b, c] for the last node, so the
// Hessian of L_rho is a band matrix of bandwidth kBandwidth.
struct VariableLayout {
  int grid_points = 0;
  static constexpr int kBandwidth = 6;  // a_k couples with c_{k+1} through the right-end rows
  [[nodiscard]] int intervals() const { return grid_points - 1; }
  [[nodiscard]] int a(int k) const { return 4 * k; }
  [[nodiscard]] int b(int k) const { return k < intervals() ? 4 * k + 1 : 4 * k; }
  [[nodiscard]] int c(int k) const { return k < intervals() ? 4 * k + 2 : 4 * k + 1; }
  [[nodiscard]] int d(int k) const { return 4 * k + 3; }
  [[nodiscard]] int size() const { return 4 * grid_points - 2; }
  // What a limit row of interval k reads (LinearRow::value's arguments).
  struct Row {
    int a, b0, b1, c0, c1;
  };
  // {a(k), b(k), b(k + 1), c(k), c(k + 1)} for k < intervals(), without a branch per entry: only
  // node k + 1 can be the last.
  [[nodiscard]] Row row(int k) const {
    const int next = 4 * (k + 1) + static_cast<int>(k + 1 < intervals());
    return {4 * k, 4 * k + 1, next, 4 * k + 2, next + 1};
  }
  // The values the boundary equalities pin, in the order of their multipliers (Multipliers::equality).
  [[nodiscard]] std::array<int, 4> boundary() const { return {b(0), b(grid_points - 1), c(0), c(grid_points - 1)}; }
};

struct Multipliers {
  Eigen::VectorXd time_cone;      // mu, 3 per interval
  Eigen::VectorXd speed_cone;     // mu, 3 per node
  Eigen::VectorXd speed_square;   // nu, 1 per node
  Eigen::VectorXd equality;       // lambda: one per interval, then b_0, b_{K-1}, c_0, c_{K-1}
  Eigen::VectorXd row_upper;      // eta of alpha a + beta b + gamma c - hi <= 0
  Eigen::VectorXd row_lower;      // eta of lo - (alpha a + beta b + gamma c) <= 0
  Eigen::VectorXd b_nonnegative;  // eta of -b_k <= 0
  void reset(const Problem& problem);
  // The three entries of mu of time cone k (interval k) and of speed cone k (node k).
  [[nodiscard]] double* timeCone(int k) { return time_cone.data() + 3 * k; }
  [[nodiscard]] const double* timeCone(int k) const { return time_cone.data() + 3 * k; }
  [[nodiscard]] double* speedCone(int k) { return speed_cone.data() + 3 * k; }
  [[nodiscard]] const double* speedCone(int k) const { return speed_cone.data() + 3 * k; }
  // lambda of boundary equality i, in the order of VariableLayout::boundary().
  [[nodiscard]] double& boundary(int i) { return equality[equality.size() - 4 + i]; }
  [[nodiscard]] double boundary(int i) const { return equality[equality.size() - 4 + i]; }
};

struct AlReport {
  bool converged = false;
  int outer_iterations = 0;
  int inner_iterations = 0;
  int evaluations = 0;
  // Largest change of a multiplier divided by rho: constraint violation combined with
  // complementarity (for an equality it is exactly the violation).
  double primal_residual = 0.0;
  // Largest gradient entry of the Lagrangian at the new multipliers, relative to the largest
  // entry of either of its parts: the cost gradient or the constraints' (multiplier-weighted).
  double dual_residual = 0.0;
  double penalty = 0.0;
  double cost = 0.0;  // sum 2 ds_k d_k at the solution
};

// x, multipliers and penalty: the solver continues from what it is given (warm start).
struct AlState {
  Eigen::VectorXd x;
  Multipliers multipliers;
  double penalty = 0.0;  // 0: start from settings.penalty_initial
};

// Buffers reused between solves of problems of the same size.
struct AlWorkspace {
  BandedCholesky hessian;  // Gauss-Newton Hessian of L_rho at the start of an inner solve, factored
  Eigen::VectorXd x_ref;
  Eigen::VectorXd z;
  Eigen::VectorXd step;
  Eigen::VectorXd gradient;
  LbfgsWorkspace lbfgs;
};

// L_rho(x) of algorithm.md (the constant -|multiplier|^2 / (2 rho) terms dropped) and its
// gradient. grad must be sized like x.
double augmentedLagrangian(const Problem& problem, const Multipliers& m, double rho, const Eigen::VectorXd& x,
                           Eigen::VectorXd& grad);

// Warm start x from a profile b (K values): a from the b-a relation, c = sqrt(b), d = 1/(c_k + c_{k+1}).
void initialGuess(const Problem& problem, const std::vector<double>& b, Eigen::VectorXd& x);

// Multipliers that make x (a reachability profile, on its constraints) stationary: the time-cone
// multipliers in closed form from the d-equations, the row multipliers by banded least squares
// on the c-equations (one per interior node), lambda from the a-equations, nu from the
// b-equations; speed-cone and b >= 0 multipliers zero. Returns the number of active rows used.
int estimateMultipliers(const Problem& problem, const Eigen::VectorXd& x, Multipliers& m);

// The (generalised) Gauss-Newton Hessian of L_rho at x, banded: cone terms through the derivative
// of the projection, c^2 = b with its curvature where the shifted residual is positive, active
// inequality rows. Plus a small floor so every variable has some curvature.
void assembleHessian(const Problem& problem, const Multipliers& m, double rho, const Eigen::VectorXd& x,
                     BandedCholesky& hessian);

// The outer loop of eqs. 30-32. Each inner minimisation is L-BFGS in the variables z of
// x = x_ref + L^{-T} z, with L L' the Hessian above at x_ref: the same minimiser, preconditioned.
AlReport solveAugmentedLagrangian(const Problem& problem, const AlSettings& settings, AlState& state,
                                  AlWorkspace& workspace);

}  // namespace cyber::planner::topp

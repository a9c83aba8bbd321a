#pragma once
// Limited-memory BFGS with the Lewis-Overton weak-Wolfe bracketing line search
// (algorithm.md sections 2.3 and 3). Generic: used by path smoothing and by the TOPP solver.

#include <functional>

#include <Eigen/Core>

namespace cyber::planner {

// The usual weak-Wolfe constants of quasi-Newton methods (Nocedal and Wright, Numerical
// Optimization, section 3.1): facts of the method, not tuned on the planner's problems.
inline constexpr double kArmijoC1 = 1e-4;
inline constexpr double kCurvatureC2 = 0.9;
// Some hundreds of ulps of a double (2.2e-16): below this share of the cost, decreases are roundoff.
inline constexpr double kRoundoffTolerance = 1e-13;
// For a direct caller; the planner's own set theirs (SmoothingSettings, ToppSettings::solver).
inline constexpr double kDefaultGradientTolerance = 1e-6;

struct LbfgsSettings {
  int memory = 8;
  int max_iterations = 200;
  double gradient_tolerance = kDefaultGradientTolerance;  // stop when the gradient's norm is below
  int max_line_search_steps = 40;
  double armijo_c1 = kArmijoC1;        // sufficient decrease (weak Wolfe condition 1)
  double curvature_c2 = kCurvatureC2;  // weak curvature condition (weak Wolfe condition 2)
  // Near the optimum, cost differences drown in roundoff and the sufficient-decrease test fails
  // on good steps. A step is then accepted by the approximate Wolfe test of Hager and Zhang
  // (slope in [c2, 1 - 2 c1] times the initial slope) if its cost is within this fraction of
  // max(1, |cost|) above the current cost. 0 disables it.
  double roundoff_tolerance = kRoundoffTolerance;
  // Optional second stopping rule (0 disables it): stop as converged when an accepted step lowers
  // the cost by less than this fraction of max(1, |cost|). Useful for inner solves.
  double relative_cost_tolerance = 0.0;
  // Length of the first trial step as a multiple of -gradient; 0 picks a unit-length move. A
  // preconditioned problem (Hessian near identity) wants 1: the Newton step.
  double first_step = 0.0;
};

enum class LbfgsStatus { kConverged, kMaxIterations, kLineSearchFailed, kNonFinite };

struct LbfgsResult {
  LbfgsStatus status;
  int iterations;
  int evaluations;
  double cost;
  double gradient_norm;
};

// f(x, grad) returns the cost and writes the gradient (grad already sized like x).
using LbfgsObjective = std::function<double(const Eigen::VectorXd&, Eigen::VectorXd&)>;

// Buffers reused between calls: a solver that runs many minimisations of the same size passes one
// workspace and allocates nothing after the first call.
struct LbfgsWorkspace {
  Eigen::MatrixXd s_history;  // n x memory, ring buffer of steps
  Eigen::MatrixXd y_history;  // n x memory, ring buffer of gradient changes
  Eigen::VectorXd rho;        // 1 / (y's) per stored pair
  Eigen::VectorXd alpha;
  Eigen::VectorXd gradient;
  Eigen::VectorXd direction;
  Eigen::VectorXd x_trial;
  Eigen::VectorXd gradient_trial;
  void resize(Eigen::Index n, int memory);
};

// Minimises f from x (updated in place to the best point found). Never throws on bad values:
// a non-finite cost or gradient at the start gives kNonFinite; non-finite trial points are
// treated as too long a step. On kLineSearchFailed x is the last accepted iterate.
LbfgsResult minimizeLbfgs(const LbfgsObjective& f, Eigen::VectorXd& x, const LbfgsSettings& settings);
LbfgsResult minimizeLbfgs(const LbfgsObjective& f, Eigen::VectorXd& x, const LbfgsSettings& settings,
                          LbfgsWorkspace& workspace);

}  // namespace cyber::planner

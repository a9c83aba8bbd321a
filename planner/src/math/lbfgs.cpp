#include "math/lbfgs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cyber::planner {

void LbfgsWorkspace::resize(Eigen::Index n, int memory) {
  if (s_history.rows() != n || s_history.cols() != memory) {
    s_history.resize(n, memory);
    y_history.resize(n, memory);
  }
  if (rho.size() != memory) {
    rho.resize(memory);
    alpha.resize(memory);
  }
  if (gradient.size() != n) {
    gradient.resize(n);
    direction.resize(n);
    x_trial.resize(n);
    gradient_trial.resize(n);
  }
}

namespace {

bool finite(const Eigen::VectorXd& v) { return v.allFinite(); }

// Two-loop recursion: direction = -H g with the stored pairs (oldest..newest in the ring).
void twoLoopDirection(LbfgsWorkspace& w, int stored, int newest, double gamma) {
  const int m = static_cast<int>(w.rho.size());
  w.direction = -w.gradient;
  for (int i = 0; i < stored; ++i) {
    const int slot = (newest - i + m) % m;
    w.alpha[slot] = w.rho[slot] * w.s_history.col(slot).dot(w.direction);
    w.direction.noalias() -= w.alpha[slot] * w.y_history.col(slot);
  }
  w.direction *= gamma;
  for (int i = stored - 1; i >= 0; --i) {
    const int slot = (newest - i + m) % m;
    const double beta = w.rho[slot] * w.y_history.col(slot).dot(w.direction);
    w.direction.noalias() += (w.alpha[slot] - beta) * w.s_history.col(slot);
  }
}

// Pairs whose curvature s'y is below this share of |s| |y| are roundoff, not curvature: storing
// one would make the inverse Hessian estimate singular or indefinite.
constexpr double kCurvatureTolerance = 1e-12;

// Evaluates f at x; the result's status is final (kNonFinite, kConverged) when there is nothing
// to iterate, kMaxIterations otherwise. Split off so that the iteration reads on its own.
LbfgsResult evaluateStart(const LbfgsObjective& f, const Eigen::VectorXd& x, const LbfgsSettings& settings,
                          LbfgsWorkspace& w, double& cost) {
  LbfgsResult result{LbfgsStatus::kMaxIterations, 0, 0, 0.0, 0.0};
  if (!finite(x)) {
    result.status = LbfgsStatus::kNonFinite;
    result.cost = std::numeric_limits<double>::quiet_NaN();
    result.gradient_norm = std::numeric_limits<double>::quiet_NaN();
    return result;
  }
  cost = f(x, w.gradient);
  ++result.evaluations;
  result.cost = cost;
  result.gradient_norm = w.gradient.norm();
  if (!std::isfinite(cost) || !finite(w.gradient)) {
    result.status = LbfgsStatus::kNonFinite;
    return result;
  }
  if (x.size() == 0 || result.gradient_norm <= settings.gradient_tolerance) {
    result.status = LbfgsStatus::kConverged;
  }
  return result;
}

// Lewis-Overton bracketing: [lo, hi] contains weak-Wolfe points; double until an upper bound is
// found, then bisect. Returns whether a step was accepted (its point in w.x_trial and
// w.gradient_trial, its cost in trial_cost); its own function so that the iteration stays short.
bool weakWolfeLineSearch(const LbfgsObjective& f, const Eigen::VectorXd& x, double cost, double slope, double step,
                         const LbfgsSettings& settings, LbfgsWorkspace& w, LbfgsResult& result, double& trial_cost) {
  double lo = 0.0;
  double hi = std::numeric_limits<double>::infinity();
  const double roundoff = settings.roundoff_tolerance * std::max(1.0, std::abs(cost));
  for (int ls = 0; ls < settings.max_line_search_steps; ++ls) {
    w.x_trial = x + step * w.direction;
    trial_cost = f(w.x_trial, w.gradient_trial);
    ++result.evaluations;
    const bool trial_finite = std::isfinite(trial_cost) && finite(w.gradient_trial);
    const double trial_slope = trial_finite ? w.gradient_trial.dot(w.direction) : 0.0;
    const bool sufficient = trial_finite && trial_cost <= cost + settings.armijo_c1 * step * slope;
    const bool approximate = trial_finite && trial_cost <= cost + roundoff &&
                             trial_slope >= settings.curvature_c2 * slope &&
                             trial_slope <= (2.0 * settings.armijo_c1 - 1.0) * slope;
    if (approximate || (sufficient && trial_slope >= settings.curvature_c2 * slope)) return true;
    if (!sufficient) {
      hi = step;
    } else {
      lo = step;
    }
    step = std::isinf(hi) ? 2.0 * lo : 0.5 * (lo + hi);
  }
  return false;
}

// Store the pair (s, y) of the accepted step; skip it when the curvature is not safely positive
// (the inverse Hessian estimate must stay positive definite).
void storePair(LbfgsWorkspace& w, const Eigen::VectorXd& x, int memory, int& newest, int& stored, double& gamma) {
  newest = (newest + 1) % memory;
  w.s_history.col(newest) = w.x_trial - x;
  w.y_history.col(newest) = w.gradient_trial - w.gradient;
  const double sy = w.s_history.col(newest).dot(w.y_history.col(newest));
  const double yy = w.y_history.col(newest).squaredNorm();
  if (sy > kCurvatureTolerance * std::sqrt(yy) * w.s_history.col(newest).norm() && yy > 0.0) {
    w.rho[newest] = 1.0 / sy;
    gamma = sy / yy;
    stored = std::min(stored + 1, memory);
  } else {
    newest = (newest - 1 + memory) % memory;
  }
}

}  // namespace

LbfgsResult minimizeLbfgs(const LbfgsObjective& f, Eigen::VectorXd& x, const LbfgsSettings& settings) {
  LbfgsWorkspace workspace;
  return minimizeLbfgs(f, x, settings, workspace);
}

LbfgsResult minimizeLbfgs(const LbfgsObjective& f, Eigen::VectorXd& x, const LbfgsSettings& settings,
                          LbfgsWorkspace& w) {
  const int memory = std::max(1, settings.memory);
  w.resize(x.size(), memory);
  double cost = 0.0;
  LbfgsResult result = evaluateStart(f, x, settings, w, cost);
  if (result.status != LbfgsStatus::kMaxIterations) return result;

  int stored = 0;
  int newest = memory - 1;
  double gamma = 1.0;
  for (int iteration = 0; iteration < settings.max_iterations; ++iteration) {
    twoLoopDirection(w, stored, newest, gamma);
    double slope = w.gradient.dot(w.direction);
    if (!(slope < 0.0) || !std::isfinite(slope)) {
      // The quasi-Newton model lost descent (possible on nonsmooth costs): restart from -g.
      stored = 0;
      w.direction = -w.gradient;
      slope = w.gradient.dot(w.direction);
    }
    // Without curvature information the first trial step moves a unit distance.
    double step = 1.0;
    if (stored == 0) step = settings.first_step > 0.0 ? settings.first_step : std::min(1.0, 1.0 / w.direction.norm());

    double trial_cost = cost;
    if (!weakWolfeLineSearch(f, x, cost, slope, step, settings, w, result, trial_cost)) {
      result.status = LbfgsStatus::kLineSearchFailed;
      break;
    }
    storePair(w, x, memory, newest, stored, gamma);

    const double decrease = cost - trial_cost;
    x.swap(w.x_trial);
    w.gradient.swap(w.gradient_trial);
    cost = trial_cost;
    result.iterations = iteration + 1;
    result.cost = cost;
    result.gradient_norm = w.gradient.norm();
    if (result.gradient_norm <= settings.gradient_tolerance) {
      result.status = LbfgsStatus::kConverged;
      break;
    }
    if (settings.relative_cost_tolerance > 0.0 &&
        decrease <= settings.relative_cost_tolerance * std::max(1.0, std::abs(cost))) {
      result.status = LbfgsStatus::kConverged;
      break;
    }
  }
  return result;
}

}  // namespace cyber::planner

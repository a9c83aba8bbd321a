#include "timing/topp_augmented_lagrangian.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "topp_al_terms.hpp"

namespace cyber::planner::topp {
namespace {

// Initial d where the speeds at both ends of an interval are zero (a rest-to-rest move's ends):
// the interval's time is unbounded there, and any large finite value lets the solver find it.
constexpr double kRestIntervalD = 1e6;

// The multiplier-update pass of the outer loop: new multipliers and the primal residual.
double updateMultipliers(const Problem& problem, Multipliers& m, double rho, const Eigen::VectorXd& x_vector) {
  const VariableLayout v{problem.gridPoints()};
  const int kk = problem.gridPoints();
  const double* x = x_vector.data();
  double residual = 0.0;
  auto track = [&](double change) { residual = std::max(residual, std::abs(change) / rho); };
  // mu <- P_K(mu - rho (A x + b)) (eq. 30).
  auto updateCone = [&](double* mu, const Cone3& u) {
    const Cone3 p = projectOntoSecondOrderCone({mu[0] - rho * u.t, mu[1] - rho * u.x1, mu[2] - rho * u.x2});
    track(p.t - mu[0]);
    track(p.x1 - mu[1]);
    track(p.x2 - mu[2]);
    mu[0] = p.t;
    mu[1] = p.x1;
    mu[2] = p.x2;
  };
  for (int k = 0; k + 1 < kk; ++k) updateCone(m.timeCone(k), timeCone(v, x, k));
  for (int k = kFirstFree; k < kk - kFirstFree; ++k) {
    const double b = x[v.b(k)];
    const double c = x[v.c(k)];
    updateCone(m.speedCone(k), speedCone(b, c));
    const double h = c * c - b;
    track(rho * h);
    m.speed_square[k] += rho * h;
    const double eta = std::max(m.b_nonnegative[k] - rho * b, 0.0);
    track(eta - m.b_nonnegative[k]);
    m.b_nonnegative[k] = eta;
  }
  for (int k = 0; k + 1 < kk; ++k) {
    const double ds = problem.ds(k);
    const double e = baRelation(v, x, k, ds) * equalityWeight(ds);
    track(rho * e);
    m.equality[k] += rho * e;
  }
  const std::array<int, 4> boundary = v.boundary();
  const std::array<double, 4> target = boundaryTargets(problem);
  for (int i = 0; i < 4; ++i) {
    const double e = x[boundary[static_cast<size_t>(i)]] - target[static_cast<size_t>(i)];
    track(rho * e);
    m.boundary(i) += rho * e;
  }
  for (size_t i = 0; i < problem.rows.size(); ++i) {
    const LinearRow& row = problem.rows[i];
    const double r = rowValue(row, v.row(row.interval), x);
    const double up = std::max(m.row_upper[static_cast<Eigen::Index>(i)] + rho * (r - row.hi), 0.0);
    track(up - m.row_upper[static_cast<Eigen::Index>(i)]);
    m.row_upper[static_cast<Eigen::Index>(i)] = up;
    if (std::isfinite(row.lo)) {
      const double low = std::max(m.row_lower[static_cast<Eigen::Index>(i)] + rho * (row.lo - r), 0.0);
      track(low - m.row_lower[static_cast<Eigen::Index>(i)]);
      m.row_lower[static_cast<Eigen::Index>(i)] = low;
    }
  }
  return residual;
}

// Largest entry of the constraints' part of a gradient of L_rho: the gradient less the cost's.
double constraintGradient(const Problem& problem, const Eigen::VectorXd& gradient) {
  const VariableLayout v{problem.gridPoints()};
  double largest = 0.0;
  auto track = [&](double entry) { largest = std::max(largest, std::abs(entry)); };
  for (int k = 0; k < v.grid_points; ++k) {
    track(gradient[v.b(k)]);
    track(gradient[v.c(k)]);
  }
  for (int k = 0; k < v.intervals(); ++k) {
    track(gradient[v.a(k)]);
    track(gradient[v.d(k)] - costGradient(problem, k));
  }
  return largest;
}

}  // namespace

void Multipliers::reset(const Problem& problem) {
  const int kk = problem.gridPoints();
  time_cone.setZero(3 * (kk - 1));
  speed_cone.setZero(3 * kk);
  speed_square.setZero(kk);
  equality.setZero(kk + 3);
  row_upper.setZero(static_cast<Eigen::Index>(problem.rows.size()));
  row_lower.setZero(static_cast<Eigen::Index>(problem.rows.size()));
  b_nonnegative.setZero(kk);
}

void initialGuess(const Problem& problem, const std::vector<double>& b, Eigen::VectorXd& x) {
  const VariableLayout v{problem.gridPoints()};
  const int kk = problem.gridPoints();
  x.resize(v.size());
  for (int k = 0; k < kk; ++k) {
    x[v.b(k)] = b[static_cast<size_t>(k)];
    x[v.c(k)] = std::sqrt(std::max(0.0, b[static_cast<size_t>(k)]));
  }
  for (int k = 0; k + 1 < kk; ++k) {
    x[v.a(k)] = (b[static_cast<size_t>(k) + 1] - b[static_cast<size_t>(k)]) / (2.0 * problem.ds(k));
    const double sigma = x[v.c(k)] + x[v.c(k + 1)];
    x[v.d(k)] = sigma > 0.0 ? 1.0 / sigma : kRestIntervalD;
  }
}

namespace {

// The terms of L_rho (eq. 21) at xs, each adding to value and g in the order of the original sum:
// one function per kind of constraint, so each reads alone.
struct AlTerms {
  const Problem& problem;
  const Multipliers& m;
  VariableLayout v;
  double rho;
  double inv_rho;
  const double* xs;
  double* g;
  double value;

  // Cost and time cones (eq. 21 with the projection P_K).
  void timeCones() {
    const int kk = problem.gridPoints();
    for (int k = 0; k + 1 < kk; ++k) {
      const Cone3 p = projectOntoSecondOrderCone(shiftedCone(m.timeCone(k), inv_rho, timeCone(v, xs, k)));
      const double cost = costGradient(problem, k);
      value += cost * xs[v.d(k)];
      g[v.d(k)] += cost;
      value += 0.5 * rho * (p.t * p.t + p.x1 * p.x1 + p.x2 * p.x2);
      const double sum = rho * (p.t + p.x1);
      g[v.c(k)] -= sum;
      g[v.c(k + 1)] -= sum;
      g[v.d(k)] -= rho * (p.t - p.x1);
    }
  }

  // Speed cones, c^2 = b, b >= 0.
  void speedCones() {
    const int kk = problem.gridPoints();
    for (int k = kFirstFree; k < kk - kFirstFree; ++k) {
      const double b = xs[v.b(k)];
      const double c = xs[v.c(k)];
      const Cone3 p = projectOntoSecondOrderCone(shiftedCone(m.speedCone(k), inv_rho, speedCone(b, c)));
      value += 0.5 * rho * (p.t * p.t + p.x1 * p.x1 + p.x2 * p.x2);
      g[v.b(k)] -= rho * (p.t + p.x1);
      g[v.c(k)] -= 2.0 * rho * p.x2;

      const double h = c * c - b + m.speed_square[k] * inv_rho;
      value += 0.5 * rho * h * h;
      g[v.c(k)] += 2.0 * rho * h * c;
      g[v.b(k)] -= rho * h;

      const double neg = -b + m.b_nonnegative[k] * inv_rho;
      if (neg > 0.0) {
        value += 0.5 * rho * neg * neg;
        g[v.b(k)] -= rho * neg;
      }
    }
  }

  // Linear equalities.
  void equalities() {
    const int kk = problem.gridPoints();
    for (int k = 0; k + 1 < kk; ++k) {
      const double ds = problem.ds(k);
      const double w = equalityWeight(ds);
      const double e = baRelation(v, xs, k, ds) * w + m.equality[k] * inv_rho;
      value += 0.5 * rho * e * e;
      const double ge = rho * e * w;
      g[v.b(k + 1)] += ge;
      g[v.b(k)] -= ge;
      g[v.a(k)] -= 2.0 * ds * ge;
    }
  }

  // Boundary values. c is pinned as well as b: at rest c^2 = b alone does not hold c at 0 to first
  // order (no constraint qualification), which would leave the multipliers unbounded.
  void boundaryValues() {
    const std::array<int, 4> index = v.boundary();
    const std::array<double, 4> target = boundaryTargets(problem);
    for (int i = 0; i < 4; ++i) {
      const auto n = static_cast<size_t>(i);
      const double e = xs[index[n]] - target[n] + m.boundary(i) * inv_rho;
      value += 0.5 * rho * e * e;
      g[index[n]] += rho * e;
    }
  }

  // Limit rows.
  void limitRows() {
    const double* up = m.row_upper.data();
    const double* low = m.row_lower.data();
    const size_t rows = problem.rows.size();
    for (size_t i = 0; i < rows; ++i) {
      const LinearRow& row = problem.rows[i];
      const VariableLayout::Row at = v.row(row.interval);
      const double r = rowValue(row, at, xs);
      double t = r - row.hi + up[i] * inv_rho;
      if (t <= 0.0) t = 0.0;
      double l = row.lo - r + low[i] * inv_rho;  // -inf for one-sided rows
      if (!(l > 0.0)) l = 0.0;
      if (t > 0.0 || l > 0.0) {
        value += 0.5 * rho * (t * t + l * l);
        const double coef = rho * (t - l);
        const double w1 = row.at;
        const double w0 = 1.0 - w1;
        g[at.a] += coef * row.alpha;
        g[at.b0] += coef * row.beta * w0;
        g[at.b1] += coef * row.beta * w1;
        g[at.c0] += coef * row.gamma * w0;
        g[at.c1] += coef * row.gamma * w1;
      }
    }
  }
};

// |L|_inf of the factor's lower triangle: |g_x|_inf <= |L|_inf |g_z|_2, so it turns the x
// target into a z tolerance.
double lowerInfinityNorm(const BandedCholesky& hessian, Eigen::Index n) {
  double l_norm = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    double row = 0.0;
    for (Eigen::Index j = std::max<Eigen::Index>(0, i - VariableLayout::kBandwidth); j <= i; ++j) {
      row += std::abs(hessian.entry(i, j));
    }
    l_norm = std::max(l_norm, row);
  }
  return l_norm;
}

}  // namespace

double augmentedLagrangian(const Problem& problem, const Multipliers& m, double rho, const Eigen::VectorXd& x,
                           Eigen::VectorXd& grad) {
  grad.setZero();
  AlTerms terms{problem, m, VariableLayout{problem.gridPoints()}, rho, 1.0 / rho, x.data(), grad.data(), 0.0};
  terms.timeCones();
  terms.speedCones();
  terms.equalities();
  terms.boundaryValues();
  terms.limitRows();
  return terms.value;
}

namespace {

// One outer step's inner minimisation at fixed multipliers and penalty: short L-BFGS runs, each
// preconditioned by the Hessian where it starts (when the active set moves on, a fresh
// factorisation beats more quasi-Newton updates). Returns the last run's result.
template <class Preconditioned>
LbfgsResult minimizeInner(const Problem& problem, const AlSettings& settings, AlState& state, AlWorkspace& w,
                          double rho, double target, Preconditioned& preconditioned, AlReport& report) {
  const Eigen::Index n = w.z.size();
  Eigen::VectorXd& x = state.x;
  LbfgsResult r{LbfgsStatus::kMaxIterations, 0, 0, 0.0, 0.0};
  int inner_used = 0;
  while (inner_used < settings.max_inner_iterations) {
    assembleHessian(problem, state.multipliers, rho, x, w.hessian);
    w.hessian.factor();
    const double l_norm = lowerInfinityNorm(w.hessian, n);
    LbfgsSettings inner;
    inner.memory = settings.lbfgs_memory;
    inner.max_iterations = std::min(settings.refresh_interval, settings.max_inner_iterations - inner_used);
    inner.gradient_tolerance = 0.5 * target / l_norm;
    inner.first_step = 1.0;
    w.x_ref = x;
    w.z.setZero();
    r = minimizeLbfgs(preconditioned, w.z, inner, w.lbfgs);
    w.step = w.z;
    w.hessian.solveUpper(w.step);
    x = w.x_ref + w.step;
    inner_used += std::max(1, r.iterations);
    report.evaluations += r.evaluations;
    if (r.status != LbfgsStatus::kMaxIterations) break;
    // The preconditioned test is only sufficient (|g| <= |L| |g_z|): stop once the gradient itself
    // meets the target.
    augmentedLagrangian(problem, state.multipliers, rho, x, w.gradient);
    ++report.evaluations;
    if (w.gradient.lpNorm<Eigen::Infinity>() <= target) break;
  }
  report.inner_iterations += inner_used;
  return r;
}

}  // namespace

AlReport solveAugmentedLagrangian(const Problem& problem, const AlSettings& settings, AlState& state, AlWorkspace& w) {
  AlReport report;
  const VariableLayout v{problem.gridPoints()};
  const int n = v.size();
  double rho = state.penalty > 0.0 ? state.penalty : settings.penalty_initial;
  double cost_gradient = 0.0;
  for (int k = 0; k < v.intervals(); ++k) cost_gradient = std::max(cost_gradient, costGradient(problem, k));

  w.z.resize(n);
  w.step.resize(n);
  w.gradient.resize(n);
  Eigen::VectorXd& x = state.x;
  // x = x_ref + L^{-T} z, gradient in z = L^{-1} gradient in x.
  auto preconditioned = [&](const Eigen::VectorXd& z, Eigen::VectorXd& gz) {
    w.step = z;
    w.hessian.solveUpper(w.step);
    x = w.x_ref + w.step;
    const double value = augmentedLagrangian(problem, state.multipliers, rho, x, w.gradient);
    gz = w.gradient;
    w.hessian.solveLower(gz);
    return value;
  };

  double primal = std::numeric_limits<double>::infinity();
  double gradient_scale = cost_gradient;
  for (int outer = 0; outer < settings.max_outer_iterations; ++outer) {
    // Early outer steps need no more accuracy than their constraint violation.
    const double target =
        std::max(settings.dual_tolerance, std::min(settings.inner_target_cap, settings.inner_target_share * primal)) *
        gradient_scale;
    const LbfgsResult r = minimizeInner(problem, settings, state, w, rho, target, preconditioned, report);
    if (r.status == LbfgsStatus::kNonFinite) break;

    augmentedLagrangian(problem, state.multipliers, rho, x, w.gradient);
    ++report.evaluations;
    // Relative to the larger of the two parts of the Lagrangian's gradient (cost, constraints):
    // with large multipliers (sharp bends) the gradient cannot be resolved below their roundoff.
    gradient_scale = std::max(cost_gradient, constraintGradient(problem, w.gradient));
    report.dual_residual = w.gradient.lpNorm<Eigen::Infinity>() / gradient_scale;
    primal = updateMultipliers(problem, state.multipliers, rho, x);
    report.primal_residual = primal;
    report.outer_iterations = outer + 1;
    if (primal <= settings.primal_tolerance && report.dual_residual <= settings.dual_tolerance) {
      report.converged = true;
      break;
    }
    rho = std::min((1.0 + settings.penalty_growth) * rho, settings.penalty_max);
  }
  state.penalty = rho;
  report.penalty = rho;
  report.cost = 0.0;
  for (int k = 0; k + 1 < problem.gridPoints(); ++k) report.cost += 2.0 * problem.ds(k) * x[v.d(k)];
  return report;
}

}  // namespace cyber::planner::topp

#include "cyber/planner/topp_augmented_lagrangian.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "cyber/planner/second_order_cone.hpp"

namespace cyber::planner::topp {
namespace {

// The b-a relation is imposed as (b_{k+1} - b_k - 2 ds a_k) / sqrt(2 ds): between the rows of
// order one in a (weight 1/(2 ds)) and in b (weight 1), so that neither the curvature rho w^2 in
// b (roundoff in the gradient on fine grids) nor the weak coupling of a dominates.
double equalityWeight(double ds) { return 1.0 / std::sqrt(2.0 * ds); }

// The multiplier-update pass of the outer loop: new multipliers and the primal residual.
double updateMultipliers(const Problem& problem, Multipliers& m, double rho, const Eigen::VectorXd& x) {
  const VariableLayout v{problem.gridPoints()};
  const int kk = problem.gridPoints();
  double residual = 0.0;
  auto track = [&](double change) { residual = std::max(residual, std::abs(change) / rho); };
  for (int k = 0; k + 1 < kk; ++k) {
    const double sigma = x[v.c(k)] + x[v.c(k + 1)];
    const double d = x[v.d(k)];
    double* mu = m.time_cone.data() + 3 * k;
    const Cone3 p = projectOntoSecondOrderCone({mu[0] - rho * (sigma + d), mu[1] - rho * (sigma - d), mu[2] - rho * 2.0});
    track(p.t - mu[0]);
    track(p.x1 - mu[1]);
    track(p.x2 - mu[2]);
    mu[0] = p.t;
    mu[1] = p.x1;
    mu[2] = p.x2;
  }
  for (int k = 0; k < kk; ++k) {
    const double b = x[v.b(k)];
    const double c = x[v.c(k)];
    double* mu = m.speed_cone.data() + 3 * k;
    const Cone3 p = projectOntoSecondOrderCone({mu[0] - rho * (b + 1.0), mu[1] - rho * (b - 1.0), mu[2] - rho * 2.0 * c});
    track(p.t - mu[0]);
    track(p.x1 - mu[1]);
    track(p.x2 - mu[2]);
    mu[0] = p.t;
    mu[1] = p.x1;
    mu[2] = p.x2;
    const double h = c * c - b;
    track(rho * h);
    m.speed_square[k] += rho * h;
    const double eta = std::max(m.b_nonnegative[k] - rho * b, 0.0);
    track(eta - m.b_nonnegative[k]);
    m.b_nonnegative[k] = eta;
  }
  for (int k = 0; k + 1 < kk; ++k) {
    const double ds = problem.ds(k);
    const double e = (x[v.b(k + 1)] - x[v.b(k)] - 2.0 * ds * x[v.a(k)]) * equalityWeight(ds);
    track(rho * e);
    m.equality[k] += rho * e;
  }
  const double boundary[4] = {x[v.b(0)] - problem.b_start, x[v.b(kk - 1)] - problem.b_end,
                              x[v.c(0)] - std::sqrt(problem.b_start), x[v.c(kk - 1)] - std::sqrt(problem.b_end)};
  for (int i = 0; i < 4; ++i) {
    track(rho * boundary[i]);
    m.equality[kk - 1 + i] += rho * boundary[i];
  }
  for (size_t i = 0; i < problem.rows.size(); ++i) {
    const LinearRow& row = problem.rows[i];
    const double r = row.alpha * x[v.a(row.interval)] + row.beta * x[v.b(row.node)] + row.gamma * x[v.c(row.node)];
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

// Derivative of the projection onto Q3 at v (symmetric 3x3): the Hessian of |P_K(v)|^2 / 2.
void projectionDerivative(const Cone3& v, double out[3][3]) {
  const double norm = std::sqrt(v.x1 * v.x1 + v.x2 * v.x2);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i][j] = 0.0;
  // On (or within roundoff of) a boundary the one-sided derivative of the boundary region is
  // used: a warm start sits exactly on the constraints and is about to cross them.
  const double band = 1e-9 * (std::abs(v.t) + norm);
  if (norm < v.t - band) {
    out[0][0] = out[1][1] = out[2][2] = 1.0;
    return;
  }
  if (norm < -v.t - band || norm == 0.0) return;
  const double u1 = v.x1 / norm;
  const double u2 = v.x2 / norm;
  const double ratio = v.t / norm;
  out[0][0] = 0.5;
  out[0][1] = out[1][0] = 0.5 * u1;
  out[0][2] = out[2][0] = 0.5 * u2;
  out[1][1] = 0.5 * (1.0 + ratio - ratio * u1 * u1);
  out[2][2] = 0.5 * (1.0 + ratio - ratio * u2 * u2);
  out[1][2] = out[2][1] = -0.5 * ratio * u1 * u2;
}

// H += rho * A' P A for a cone term whose argument u = A x (+ const) touches `count` variables.
template <int N>
void addConeTerm(BandedCholesky& h, double rho, const Cone3& v, const int (&index)[N], const double (&a)[3][N]) {
  double p[3][3];
  projectionDerivative(v, p);
  double pa[3][N];
  for (int r = 0; r < 3; ++r)
    for (int j = 0; j < N; ++j) pa[r][j] = p[r][0] * a[0][j] + p[r][1] * a[1][j] + p[r][2] * a[2][j];
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j <= i; ++j) {
      const double value = rho * (a[0][i] * pa[0][j] + a[1][i] * pa[1][j] + a[2][i] * pa[2][j]);
      if (value != 0.0) h.add(index[i], index[j], value);
    }
  }
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
    x[v.d(k)] = sigma > 0.0 ? 1.0 / sigma : 1e6;
  }
}

double augmentedLagrangian(const Problem& problem, const Multipliers& m, double rho, const Eigen::VectorXd& x,
                           Eigen::VectorXd& grad) {
  const VariableLayout v{problem.gridPoints()};
  const int kk = problem.gridPoints();
  const double inv_rho = 1.0 / rho;
  grad.setZero();
  double* g = grad.data();
  const double* xs = x.data();
  double value = 0.0;

  // Cost and time cones (eq. 21 with the projection P_K).
  for (int k = 0; k + 1 < kk; ++k) {
    const double ds = problem.ds(k);
    const double sigma = xs[v.c(k)] + xs[v.c(k + 1)];
    const double d = xs[v.d(k)];
    value += problem.cost_scale * 2.0 * ds * d;
    g[v.d(k)] += problem.cost_scale * 2.0 * ds;
    const double* mu = m.time_cone.data() + 3 * k;
    const Cone3 p = projectOntoSecondOrderCone(
        {mu[0] * inv_rho - (sigma + d), mu[1] * inv_rho - (sigma - d), mu[2] * inv_rho - 2.0});
    value += 0.5 * rho * (p.t * p.t + p.x1 * p.x1 + p.x2 * p.x2);
    const double sum = rho * (p.t + p.x1);
    g[v.c(k)] -= sum;
    g[v.c(k + 1)] -= sum;
    g[v.d(k)] -= rho * (p.t - p.x1);
  }
  // Speed cones, c^2 = b, b >= 0.
  for (int k = 0; k < kk; ++k) {
    const double b = xs[v.b(k)];
    const double c = xs[v.c(k)];
    const double* mu = m.speed_cone.data() + 3 * k;
    const Cone3 p = projectOntoSecondOrderCone(
        {mu[0] * inv_rho - (b + 1.0), mu[1] * inv_rho - (b - 1.0), mu[2] * inv_rho - 2.0 * c});
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
  // Linear equalities.
  for (int k = 0; k + 1 < kk; ++k) {
    const double ds = problem.ds(k);
    const double w = equalityWeight(ds);
    const double e = (xs[v.b(k + 1)] - xs[v.b(k)] - 2.0 * ds * xs[v.a(k)]) * w + m.equality[k] * inv_rho;
    value += 0.5 * rho * e * e;
    const double ge = rho * e * w;
    g[v.b(k + 1)] += ge;
    g[v.b(k)] -= ge;
    g[v.a(k)] -= 2.0 * ds * ge;
  }
  // Boundary values. c is pinned as well as b: at rest c^2 = b alone does not hold c at 0 to first
  // order (no constraint qualification), which would leave the multipliers unbounded.
  {
    const int index[4] = {v.b(0), v.b(kk - 1), v.c(0), v.c(kk - 1)};
    const double target[4] = {problem.b_start, problem.b_end, std::sqrt(problem.b_start), std::sqrt(problem.b_end)};
    for (int i = 0; i < 4; ++i) {
      const double e = xs[index[i]] - target[i] + m.equality[kk - 1 + i] * inv_rho;
      value += 0.5 * rho * e * e;
      g[index[i]] += rho * e;
    }
  }
  // Limit rows.
  const double* up = m.row_upper.data();
  const double* low = m.row_lower.data();
  const size_t rows = problem.rows.size();
  for (size_t i = 0; i < rows; ++i) {
    const LinearRow& row = problem.rows[i];
    const int ia = v.a(row.interval);
    const int ib = v.b(row.node);
    const int ic = v.c(row.node);
    const double r = row.alpha * xs[ia] + row.beta * xs[ib] + row.gamma * xs[ic];
    double t = r - row.hi + up[i] * inv_rho;
    if (t <= 0.0) t = 0.0;
    double l = row.lo - r + low[i] * inv_rho;  // -inf for one-sided rows
    if (!(l > 0.0)) l = 0.0;
    if (t > 0.0 || l > 0.0) {
      value += 0.5 * rho * (t * t + l * l);
      const double coef = rho * (t - l);
      g[ia] += coef * row.alpha;
      g[ib] += coef * row.beta;
      g[ic] += coef * row.gamma;
    }
  }
  return value;
}

int estimateMultipliers(const Problem& problem, const Eigen::VectorXd& x, Multipliers& m) {
  const VariableLayout v{problem.gridPoints()};
  const int kk = problem.gridPoints();
  m.reset(problem);
  if (kk < 3) return 0;
  constexpr double kActive = 1e-9;

  // Active rows (index, +1 upper / -1 lower), in interval order.
  struct Active {
    int row;
    double sign;
  };
  std::vector<Active> active;
  active.reserve(problem.rows.size());
  for (size_t i = 0; i < problem.rows.size(); ++i) {
    const LinearRow& row = problem.rows[i];
    const double r = row.alpha * x[v.a(row.interval)] + row.beta * x[v.b(row.node)] + row.gamma * x[v.c(row.node)];
    if (r >= row.hi - kActive) {
      active.push_back({static_cast<int>(i), 1.0});
    } else if (std::isfinite(row.lo) && r <= row.lo + kActive) {
      active.push_back({static_cast<int>(i), -1.0});
    }
  }
  // Time cones on their boundary: mu = theta (sigma + d, -(sigma - d), -2), theta = cost ds / sigma.
  std::vector<double> pull(static_cast<size_t>(kk), 0.0);  // R_n = sum over adjacent cones of 2 theta d
  for (int k = 0; k + 1 < kk; ++k) {
    const double sigma = x[v.c(k)] + x[v.c(k + 1)];
    const double d = x[v.d(k)];
    if (!(sigma > 0.0)) continue;
    const double theta = problem.cost_scale * problem.ds(k) / sigma;
    m.time_cone[3 * k] = theta * (sigma + d);
    m.time_cone[3 * k + 1] = -theta * (sigma - d);
    m.time_cone[3 * k + 2] = -2.0 * theta;
    pull[static_cast<size_t>(k)] += 2.0 * theta * d;
    pull[static_cast<size_t>(k) + 1] += 2.0 * theta * d;
  }

  // Equation of interior node n: 2 c_n nu_n + sum_{rows at n} zeta gamma = R_n, with
  // nu_n = A_{n-1}/(2 ds_{n-1}) - A_n/(2 ds_n) + sum_{rows at n} zeta beta, A_k = sum_{rows of k} zeta alpha.
  // Coefficient of a row's zeta in the equations of its interval's two nodes:
  auto coefficient = [&](const LinearRow& row, int n) {
    const double c = x[v.c(n)];
    const double inv = 1.0 / (2.0 * problem.ds(row.interval));
    double value = (n == row.interval + 1 ? 1.0 : -1.0) * 2.0 * c * row.alpha * inv;
    if (row.node == n) value += 2.0 * c * row.beta + row.gamma;
    return value;
  };
  // Least squares over the active rows; a row whose multiplier comes out with the wrong sign is
  // dropped (its multiplier is zero) and the rest solved again: a few passes of an active-set
  // non-negative least squares, each O(K).
  Eigen::VectorXd rhs;
  for (int pass = 0; pass < 8 && !active.empty(); ++pass) {
    const auto unknowns = static_cast<Eigen::Index>(active.size());
    // Bandwidth of J'J: rows sharing an equation lie in the same or adjacent intervals.
    int bandwidth = 0;
    for (size_t i = 0, first = 0; i < active.size(); ++i) {
      const int interval = problem.rows[static_cast<size_t>(active[i].row)].interval;
      while (problem.rows[static_cast<size_t>(active[first].row)].interval < interval - 1) ++first;
      bandwidth = std::max(bandwidth, static_cast<int>(i - first));
    }
    BandedCholesky normal;
    normal.reset(unknowns, bandwidth);
    rhs = Eigen::VectorXd::Zero(unknowns);
    // J'J and J'R equation by equation (each equation touches a contiguous run of rows).
    size_t first = 0;
    for (int n = 1; n + 1 < kk; ++n) {
      while (first < active.size() && problem.rows[static_cast<size_t>(active[first].row)].interval < n - 1) ++first;
      size_t last = first;
      while (last < active.size() && problem.rows[static_cast<size_t>(active[last].row)].interval <= n) ++last;
      for (size_t i = first; i < last; ++i) {
        const double ci = coefficient(problem.rows[static_cast<size_t>(active[i].row)], n);
        rhs[static_cast<Eigen::Index>(i)] += ci * pull[static_cast<size_t>(n)];
        for (size_t j = first; j <= i; ++j) {
          const double cj = coefficient(problem.rows[static_cast<size_t>(active[j].row)], n);
          normal.add(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j), ci * cj);
        }
      }
    }
    double max_diag = 0.0;
    for (Eigen::Index i = 0; i < unknowns; ++i) max_diag = std::max(max_diag, normal.entry(i, i));
    for (Eigen::Index i = 0; i < unknowns; ++i) normal.add(i, i, 1e-10 * max_diag + 1e-300);
    normal.factor();
    normal.solveLower(rhs);
    normal.solveUpper(rhs);
    size_t kept = 0;
    for (size_t i = 0; i < active.size(); ++i) {
      if (active[i].sign * rhs[static_cast<Eigen::Index>(i)] >= 0.0) {
        rhs[static_cast<Eigen::Index>(kept)] = rhs[static_cast<Eigen::Index>(i)];
        active[kept++] = active[i];
      }
    }
    if (kept == active.size()) break;
    active.resize(kept);
  }
  if (active.empty()) rhs.resize(0);

  // Keep the sign each active side allows; derive lambda and nu from the a- and b-equations.
  std::vector<double> a_sum(static_cast<size_t>(kk - 1), 0.0);
  std::vector<double> b_sum(static_cast<size_t>(kk), 0.0);
  for (size_t i = 0; i < active.size(); ++i) {
    const auto row_index = static_cast<Eigen::Index>(active[i].row);
    const LinearRow& row = problem.rows[static_cast<size_t>(row_index)];
    const double zeta = rhs[static_cast<Eigen::Index>(i)];
    const double eta = std::max(0.0, active[i].sign * zeta);
    (active[i].sign > 0.0 ? m.row_upper : m.row_lower)[row_index] = eta;
    a_sum[static_cast<size_t>(row.interval)] += active[i].sign * eta * row.alpha;
    b_sum[static_cast<size_t>(row.node)] += active[i].sign * eta * row.beta;
  }
  for (int k = 0; k + 1 < kk; ++k) m.equality[k] = a_sum[static_cast<size_t>(k)];
  for (int n = 1; n + 1 < kk; ++n) {
    m.speed_square[n] = a_sum[static_cast<size_t>(n) - 1] / (2.0 * problem.ds(n - 1)) -
                        a_sum[static_cast<size_t>(n)] / (2.0 * problem.ds(n)) + b_sum[static_cast<size_t>(n)];
  }
  // End nodes: nu = 0 there; the boundary-value multipliers take up the b- and c-equations.
  std::vector<double> c_sum(static_cast<size_t>(kk), 0.0);
  for (size_t i = 0; i < active.size(); ++i) {
    const LinearRow& row = problem.rows[static_cast<size_t>(active[i].row)];
    const double eta = (active[i].sign > 0.0 ? m.row_upper : m.row_lower)[active[i].row];
    c_sum[static_cast<size_t>(row.node)] += active[i].sign * eta * row.gamma;
  }
  const auto last = static_cast<size_t>(kk - 1);
  m.equality[kk - 1] = a_sum[0] / (2.0 * problem.ds(0)) - b_sum[0];
  m.equality[kk] = -a_sum[last - 1] / (2.0 * problem.ds(kk - 2)) - b_sum[last];
  m.equality[kk + 1] = pull[0] - c_sum[0];
  m.equality[kk + 2] = pull[last] - c_sum[last];
  return static_cast<int>(active.size());
}

void assembleHessian(const Problem& problem, const Multipliers& m, double rho, const Eigen::VectorXd& x,
                     BandedCholesky& h) {
  const VariableLayout v{problem.gridPoints()};
  const int kk = problem.gridPoints();
  const double inv_rho = 1.0 / rho;
  h.reset(v.size(), VariableLayout::kBandwidth);
  // Floor: a small multiple of the curvature each variable would have with every term active.
  Eigen::VectorXd floor = Eigen::VectorXd::Zero(v.size());

  for (int k = 0; k + 1 < kk; ++k) {
    const double sigma = x[v.c(k)] + x[v.c(k + 1)];
    const double d = x[v.d(k)];
    const double* mu = m.time_cone.data() + 3 * k;
    const Cone3 arg{mu[0] * inv_rho - (sigma + d), mu[1] * inv_rho - (sigma - d), mu[2] * inv_rho - 2.0};
    const int index[3] = {v.c(k), v.c(k + 1), v.d(k)};
    const double a[3][3] = {{1.0, 1.0, 1.0}, {1.0, 1.0, -1.0}, {0.0, 0.0, 0.0}};
    addConeTerm<3>(h, rho, arg, index, a);
    floor[v.c(k)] += 2.0;
    floor[v.c(k + 1)] += 2.0;
    floor[v.d(k)] += 2.0;

    const double ds = problem.ds(k);
    const double w = equalityWeight(ds);
    const int eq_index[3] = {v.a(k), v.b(k), v.b(k + 1)};
    const double eq[3] = {-2.0 * ds * w, -w, w};
    for (int i = 0; i < 3; ++i) {
      floor[eq_index[i]] += eq[i] * eq[i];
      for (int j = 0; j <= i; ++j) h.add(eq_index[i], eq_index[j], rho * eq[i] * eq[j]);
    }
  }
  for (int k = 0; k < kk; ++k) {
    const double b = x[v.b(k)];
    const double c = x[v.c(k)];
    const double* mu = m.speed_cone.data() + 3 * k;
    const Cone3 arg{mu[0] * inv_rho - (b + 1.0), mu[1] * inv_rho - (b - 1.0), mu[2] * inv_rho - 2.0 * c};
    const int index[2] = {v.b(k), v.c(k)};
    const double a[3][2] = {{1.0, 0.0}, {1.0, 0.0}, {0.0, 2.0}};
    addConeTerm<2>(h, rho, arg, index, a);
    floor[v.b(k)] += 2.0;
    floor[v.c(k)] += 4.0;

    // (c^2 - b + nu/rho)^2: Gauss-Newton part plus its own curvature when that helps.
    const double shifted = c * c - b + m.speed_square[k] * inv_rho;
    h.add(v.b(k), v.b(k), rho);
    h.add(v.c(k), v.b(k), -2.0 * rho * c);
    h.add(v.c(k), v.c(k), 4.0 * rho * c * c + 2.0 * rho * std::max(0.0, shifted));
    floor[v.b(k)] += 1.0;
    floor[v.c(k)] += 4.0 * c * c + 1.0;

    if (-b + m.b_nonnegative[k] * inv_rho > 0.0) h.add(v.b(k), v.b(k), rho);
  }
  for (const int i : {v.b(0), v.b(kk - 1), v.c(0), v.c(kk - 1)}) {
    h.add(i, i, rho);
    floor[i] += 1.0;
  }

  for (size_t i = 0; i < problem.rows.size(); ++i) {
    const LinearRow& row = problem.rows[i];
    const int index[3] = {v.a(row.interval), v.b(row.node), v.c(row.node)};
    const double coef[3] = {row.alpha, row.beta, row.gamma};
    const double r = row.alpha * x[index[0]] + row.beta * x[index[1]] + row.gamma * x[index[2]];
    // Rows at or near their bound count as active: the minimiser is about to push past them,
    // and a row that just stepped inside still bounds how far the next step may go.
    const double near = 1e-9 * (1.0 + std::abs(r));
    const bool active = r - row.hi + m.row_upper[static_cast<Eigen::Index>(i)] * inv_rho > -near ||
                        row.lo - r + m.row_lower[static_cast<Eigen::Index>(i)] * inv_rho > -near;
    for (int p = 0; p < 3; ++p) {
      floor[index[p]] += coef[p] * coef[p];
      if (!active) continue;
      for (int q = 0; q <= p; ++q) {
        if (coef[p] != 0.0 && coef[q] != 0.0) h.add(index[p], index[q], rho * coef[p] * coef[q]);
      }
    }
  }
  constexpr double kFloor = 1e-6;
  for (Eigen::Index i = 0; i < floor.size(); ++i) h.add(i, i, kFloor * rho * floor[i]);
}

AlReport solveAugmentedLagrangian(const Problem& problem, const AlSettings& settings, AlState& state,
                                  AlWorkspace& w) {
  AlReport report;
  const VariableLayout v{problem.gridPoints()};
  const int n = v.size();
  double rho = state.penalty > 0.0 ? state.penalty : settings.penalty_initial;
  double cost_gradient = 0.0;
  for (int k = 0; k + 1 < problem.gridPoints(); ++k) {
    cost_gradient = std::max(cost_gradient, problem.cost_scale * 2.0 * problem.ds(k));
  }

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
  for (int outer = 0; outer < settings.max_outer_iterations; ++outer) {
    // Early outer steps need no more accuracy than their constraint violation.
    const double target = std::max(settings.dual_tolerance, std::min(1e-2, 0.1 * primal)) * cost_gradient;
    LbfgsResult r{LbfgsStatus::kMaxIterations, 0, 0, 0.0, 0.0};
    int inner_used = 0;
    // The preconditioner is the Hessian where a run starts; when the active set moves on, a
    // fresh factorisation beats more quasi-Newton updates, so runs are short.
    while (inner_used < settings.max_inner_iterations) {
      assembleHessian(problem, state.multipliers, rho, x, w.hessian);
      w.hessian.factor();
      // |g_x|_inf <= |L|_inf |g_z|_2: the z tolerance that guarantees the x target.
      double l_norm = 0.0;
      for (Eigen::Index i = 0; i < n; ++i) {
        double row = 0.0;
        for (Eigen::Index j = std::max<Eigen::Index>(0, i - VariableLayout::kBandwidth); j <= i; ++j) {
          row += std::abs(w.hessian.entry(i, j));
        }
        l_norm = std::max(l_norm, row);
      }
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
    }
    report.inner_iterations += inner_used;
    if (r.status == LbfgsStatus::kNonFinite) break;

    augmentedLagrangian(problem, state.multipliers, rho, x, w.gradient);
    ++report.evaluations;
    report.dual_residual = w.gradient.lpNorm<Eigen::Infinity>() / cost_gradient;
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

// Multiplier warm start of the augmented Lagrangian (algorithm.md section 3): the multipliers
// that make the reachability profile stationary, by banded least squares.

#include <algorithm>
#include <cmath>
#include <vector>

#include "math/banded_cholesky.hpp"
#include "topp_al_terms.hpp"

namespace cyber::planner::topp {

namespace {

// A row within this of its bound (rows are of order one) is active: the reachability profile
// sits on its binding rows to roundoff.
constexpr double kActive = 1e-9;
// The normal equations are regularised by this share of their largest diagonal entry, plus the
// smallest normal double's neighbourhood, so a rank-deficient set of active rows still factors.
constexpr double kRegularisation = 1e-10;
constexpr double kRegularisationFloor = 1e-300;
constexpr int kMaxPasses = 8;  // of the active-set least squares; each drops wrong-signed rows

// An active row (index, +1 upper / -1 lower).
struct Active {
  int row;
  double sign;
};

// Active rows, in interval order.
std::vector<Active> activeRows(const Problem& problem, const VariableLayout& v, const Eigen::VectorXd& x) {
  std::vector<Active> active;
  active.reserve(problem.rows.size());
  for (size_t i = 0; i < problem.rows.size(); ++i) {
    const LinearRow& row = problem.rows[i];
    const double r = rowValue(row, v.row(row.interval), x.data());
    if (r >= row.hi - kActive) {
      active.push_back({static_cast<int>(i), 1.0});
    } else if (std::isfinite(row.lo) && r <= row.lo + kActive) {
      active.push_back({static_cast<int>(i), -1.0});
    }
  }
  return active;
}

// Time cones on their boundary: mu = theta (sigma + d, -(sigma - d), -2), theta = cost ds / sigma.
// Returns R_n = sum over adjacent cones of 2 theta d, the right-hand side of the node equations.
std::vector<double> timeConeMultipliers(const Problem& problem, const VariableLayout& v, const Eigen::VectorXd& x,
                                        Multipliers& m) {
  const int kk = problem.gridPoints();
  std::vector<double> pull(static_cast<size_t>(kk), 0.0);
  for (int k = 0; k + 1 < kk; ++k) {
    const double sigma = x[v.c(k)] + x[v.c(k + 1)];
    const double d = x[v.d(k)];
    if (!(sigma > 0.0)) continue;
    const double theta = problem.cost_scale * problem.ds(k) / sigma;
    double* mu = m.timeCone(k);
    mu[0] = theta * (sigma + d);
    mu[1] = -theta * (sigma - d);
    mu[2] = -2.0 * theta;
    pull[static_cast<size_t>(k)] += 2.0 * theta * d;
    pull[static_cast<size_t>(k) + 1] += 2.0 * theta * d;
  }
  return pull;
}

// Equation of interior node n: 2 c_n nu_n + sum_{rows at n} zeta gamma = R_n, with
// nu_n = A_{n-1}/(2 ds_{n-1}) - A_n/(2 ds_n) + sum_{rows at n} zeta beta, A_k = sum_{rows of k} zeta alpha.
// Coefficient of a row's zeta in the equations of its interval's two nodes:
double zetaCoefficient(const Problem& problem, const VariableLayout& v, const Eigen::VectorXd& x, const LinearRow& row,
                       int n) {
  const double c = x[v.c(n)];
  const double inv = 1.0 / (2.0 * problem.ds(row.interval));
  double value = (n == row.interval + 1 ? 1.0 : -1.0) * 2.0 * c * row.alpha * inv;
  const double weight = n == row.interval ? 1.0 - row.at : row.at;  // of node n in b_at, c_at
  value += weight * (2.0 * c * row.beta + row.gamma);
  return value;
}

// One pass's least squares over the active rows: J'J zeta = J'R, solved into rhs.
void solveNormalEquations(const Problem& problem, const VariableLayout& v, const Eigen::VectorXd& x,
                          const std::vector<Active>& active, const std::vector<double>& pull, Eigen::VectorXd& rhs) {
  const int kk = problem.gridPoints();
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
      const double ci = zetaCoefficient(problem, v, x, problem.rows[static_cast<size_t>(active[i].row)], n);
      rhs[static_cast<Eigen::Index>(i)] += ci * pull[static_cast<size_t>(n)];
      for (size_t j = first; j <= i; ++j) {
        const double cj = zetaCoefficient(problem, v, x, problem.rows[static_cast<size_t>(active[j].row)], n);
        normal.add(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j), ci * cj);
      }
    }
  }
  double max_diag = 0.0;
  for (Eigen::Index i = 0; i < unknowns; ++i) max_diag = std::max(max_diag, normal.entry(i, i));
  for (Eigen::Index i = 0; i < unknowns; ++i) normal.add(i, i, kRegularisation * max_diag + kRegularisationFloor);
  normal.factor();
  normal.solveLower(rhs);
  normal.solveUpper(rhs);
}

// Keep the sign each active side allows; derive lambda and nu from the a- and b-equations, and
// (nu = 0 at the end nodes) the boundary-value multipliers from the b- and c-equations.
void deriveMultipliers(const Problem& problem, const std::vector<Active>& active, const Eigen::VectorXd& rhs,
                       const std::vector<double>& pull, Multipliers& m) {
  const int kk = problem.gridPoints();
  std::vector<double> a_sum(static_cast<size_t>(kk - 1), 0.0);
  std::vector<double> b_sum(static_cast<size_t>(kk), 0.0);
  for (size_t i = 0; i < active.size(); ++i) {
    const auto row_index = static_cast<Eigen::Index>(active[i].row);
    const LinearRow& row = problem.rows[static_cast<size_t>(row_index)];
    const double zeta = rhs[static_cast<Eigen::Index>(i)];
    const double eta = std::max(0.0, active[i].sign * zeta);
    (active[i].sign > 0.0 ? m.row_upper : m.row_lower)[row_index] = eta;
    a_sum[static_cast<size_t>(row.interval)] += active[i].sign * eta * row.alpha;
    b_sum[static_cast<size_t>(row.interval)] += active[i].sign * eta * row.beta * (1.0 - row.at);
    b_sum[static_cast<size_t>(row.interval) + 1] += active[i].sign * eta * row.beta * row.at;
  }
  for (int k = 0; k + 1 < kk; ++k) m.equality[k] = a_sum[static_cast<size_t>(k)];
  for (int n = 1; n + 1 < kk; ++n) {
    m.speed_square[n] = a_sum[static_cast<size_t>(n) - 1] / (2.0 * problem.ds(n - 1)) -
                        a_sum[static_cast<size_t>(n)] / (2.0 * problem.ds(n)) + b_sum[static_cast<size_t>(n)];
  }
  std::vector<double> c_sum(static_cast<size_t>(kk), 0.0);
  for (size_t i = 0; i < active.size(); ++i) {
    const LinearRow& row = problem.rows[static_cast<size_t>(active[i].row)];
    const double eta = (active[i].sign > 0.0 ? m.row_upper : m.row_lower)[active[i].row];
    c_sum[static_cast<size_t>(row.interval)] += active[i].sign * eta * row.gamma * (1.0 - row.at);
    c_sum[static_cast<size_t>(row.interval) + 1] += active[i].sign * eta * row.gamma * row.at;
  }
  const auto last = static_cast<size_t>(kk - 1);
  m.boundary(0) = a_sum[0] / (2.0 * problem.ds(0)) - b_sum[0];
  m.boundary(1) = -a_sum[last - 1] / (2.0 * problem.ds(kk - 2)) - b_sum[last];
  m.boundary(2) = pull[0] - c_sum[0];
  m.boundary(3) = pull[last] - c_sum[last];
}

}  // namespace

int estimateMultipliers(const Problem& problem, const Eigen::VectorXd& x, Multipliers& m) {
  const VariableLayout v{problem.gridPoints()};
  const int kk = problem.gridPoints();
  m.reset(problem);
  if (kk < 3) return 0;
  std::vector<Active> active = activeRows(problem, v, x);
  const std::vector<double> pull = timeConeMultipliers(problem, v, x, m);
  // Least squares over the active rows; a row whose multiplier comes out with the wrong sign is
  // dropped (its multiplier is zero) and the rest solved again: a few passes of an active-set
  // non-negative least squares, each O(K).
  Eigen::VectorXd rhs;
  for (int pass = 0; pass < kMaxPasses && !active.empty(); ++pass) {
    solveNormalEquations(problem, v, x, active, pull, rhs);
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
  deriveMultipliers(problem, active, rhs, pull, m);
  return static_cast<int>(active.size());
}

}  // namespace cyber::planner::topp

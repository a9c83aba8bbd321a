// The banded (generalised) Gauss-Newton Hessian of L_rho (algorithm.md eqs. 19-23): the
// preconditioner of the inner L-BFGS.

#include <algorithm>
#include <array>
#include <cmath>

#include "topp_al_terms.hpp"

namespace cyber::planner::topp {
namespace {

// Within this share of |v| of a cone's boundary, v is on it (roundoff of the warm start's exact
// constraints); likewise a row within this share of its value of its bound.
constexpr double kBoundaryBand = 1e-9;
// The square of the 2 in d(c^2)/dc = 2 c: the Gauss-Newton terms of c^2 = b.
constexpr double kTwoSquared = 4.0;
// Every diagonal entry gets this share of its scale (the sum of its terms' squared coefficients):
// enough to keep the factor positive definite, far below the terms themselves.
constexpr double kFloor = 1e-6;

// Derivative of the projection onto Q3 at v (symmetric 3x3): the Hessian of |P_K(v)|^2 / 2.
void projectionDerivative(const Cone3& v, double out[3][3]) {
  const double norm = std::sqrt(v.x1 * v.x1 + v.x2 * v.x2);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i][j] = 0.0;
  // On (or within roundoff of) a boundary the one-sided derivative of the boundary region is
  // used: a warm start sits exactly on the constraints and is about to cross them.
  const double band = kBoundaryBand * (std::abs(v.t) + norm);
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

void assembleHessian(const Problem& problem, const Multipliers& m, double rho, const Eigen::VectorXd& x_vector,
                     BandedCholesky& h) {
  const VariableLayout v{problem.gridPoints()};
  const double* x = x_vector.data();
  const int kk = problem.gridPoints();
  const double inv_rho = 1.0 / rho;
  h.reset(v.size(), VariableLayout::kBandwidth);
  // Floor: a small multiple of the curvature each variable would have with every term active.
  Eigen::VectorXd floor = Eigen::VectorXd::Zero(v.size());

  for (int k = 0; k + 1 < kk; ++k) {
    const Cone3 arg = shiftedCone(m.timeCone(k), inv_rho, timeCone(v, x, k));
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
  for (int k = kFirstFree; k < kk - kFirstFree; ++k) {
    const double b = x[v.b(k)];
    const double c = x[v.c(k)];
    const Cone3 arg = shiftedCone(m.speedCone(k), inv_rho, speedCone(b, c));
    const int index[2] = {v.b(k), v.c(k)};
    const double a[3][2] = {{1.0, 0.0}, {1.0, 0.0}, {0.0, 2.0}};
    addConeTerm<2>(h, rho, arg, index, a);
    floor[v.b(k)] += 2.0;
    floor[v.c(k)] += kTwoSquared;

    // (c^2 - b + nu/rho)^2: Gauss-Newton part plus its own curvature when that helps.
    const double shifted = c * c - b + m.speed_square[k] * inv_rho;
    h.add(v.b(k), v.b(k), rho);
    h.add(v.c(k), v.b(k), -2.0 * rho * c);
    h.add(v.c(k), v.c(k), kTwoSquared * rho * c * c + 2.0 * rho * std::max(0.0, shifted));
    floor[v.b(k)] += 1.0;
    floor[v.c(k)] += kTwoSquared * c * c + 1.0;

    if (-b + m.b_nonnegative[k] * inv_rho > 0.0) h.add(v.b(k), v.b(k), rho);
  }
  for (const int i : v.boundary()) {
    h.add(i, i, rho);
    floor[i] += 1.0;
  }

  for (size_t i = 0; i < problem.rows.size(); ++i) {
    const LinearRow& row = problem.rows[i];
    const VariableLayout::Row at = v.row(row.interval);
    const int index[5] = {at.a, at.b0, at.b1, at.c0, at.c1};
    const double coef[5] = {row.alpha, row.beta * (1.0 - row.at), row.beta * row.at, row.gamma * (1.0 - row.at),
                            row.gamma * row.at};
    const double r = rowValue(row, at, x);
    // Rows at or near their bound count as active: the minimiser is about to push past them,
    // and a row that just stepped inside still bounds how far the next step may go.
    const double near = kBoundaryBand * (1.0 + std::abs(r));
    const bool active = r - row.hi + m.row_upper[static_cast<Eigen::Index>(i)] * inv_rho > -near ||
                        row.lo - r + m.row_lower[static_cast<Eigen::Index>(i)] * inv_rho > -near;
    for (int p = 0; p < 5; ++p) {
      floor[index[p]] += coef[p] * coef[p];
      if (!active || coef[p] == 0.0) continue;
      for (int q = 0; q <= p; ++q) {
        if (coef[q] != 0.0) h.add(index[p], index[q], rho * coef[p] * coef[q]);
      }
    }
  }
  for (Eigen::Index i = 0; i < floor.size(); ++i) h.add(i, i, kFloor * rho * floor[i]);
}

}  // namespace cyber::planner::topp

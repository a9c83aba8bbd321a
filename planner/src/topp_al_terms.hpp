#pragma once
// Conventions shared by the augmented Lagrangian's evaluation, Hessian, multiplier update and
// multiplier estimate (internal to the planner library): one definition of each constraint's
// value at x, so L_rho, its Hessian and the updates of eqs. 30-31 cannot drift apart.

#include <array>
#include <cmath>

#include "cyber/planner/second_order_cone.hpp"
#include "cyber/planner/topp_augmented_lagrangian.hpp"

namespace cyber::planner::topp {

// The b-a relation is imposed as (b_{k+1} - b_k - 2 ds a_k) / sqrt(2 ds): between the rows of
// order one in a (weight 1/(2 ds)) and in b (weight 1), so that neither the curvature rho w^2 in
// b (roundoff in the gradient on fine grids) nor the weak coupling of a dominates.
inline double equalityWeight(double ds) { return 1.0 / std::sqrt(2.0 * ds); }

// The end nodes' b and c are fixed by the boundary values, which imply the speed cone, c^2 = b
// and b >= 0 there; those redundant (and, at rest, degenerate: c^2 = b has no first-order hold
// on c at 0) rows are left out at the two end nodes.
inline constexpr int kFirstFree = 1;

// The cost sum_k 2 ds_k d_k (eq. 15, times cost_scale) is linear: this is its gradient at d_k,
// and zero at every other variable.
inline double costGradient(const Problem& problem, int k) { return problem.cost_scale * 2.0 * problem.ds(k); }

// The affine arguments A x + b of the time cone of interval k (eq. 16) and the speed cone of
// node k (eq. 17).
inline Cone3 timeCone(const VariableLayout& v, const double* x, int k) {
  const double sigma = x[v.c(k)] + x[v.c(k + 1)];
  const double d = x[v.d(k)];
  return {sigma + d, sigma - d, 2.0};
}
inline Cone3 speedCone(const VariableLayout& v, const double* x, int k) {
  const double b = x[v.b(k)];
  return {b + 1.0, b - 1.0, 2.0 * x[v.c(k)]};
}

// mu / rho - (A x + b): what L_rho projects (eq. 19); mu points at the cone's three multipliers.
inline Cone3 shiftedCone(const double* mu, double inv_rho, const Cone3& u) {
  return {mu[0] * inv_rho - u.t, mu[1] * inv_rho - u.x1, mu[2] * inv_rho - u.x2};
}

// b_{k+1} - b_k - 2 ds_k a_k, weighted (the linear equality of interval k).
inline double baRelation(const Problem& problem, const VariableLayout& v, const double* x, int k) {
  const double ds = problem.ds(k);
  return (x[v.b(k + 1)] - x[v.b(k)] - 2.0 * ds * x[v.a(k)]) * equalityWeight(ds);
}

// The targets of the boundary equalities, in the order of VariableLayout::boundary().
inline std::array<double, 4> boundaryTargets(const Problem& problem) {
  return {problem.b_start, problem.b_end, std::sqrt(problem.b_start), std::sqrt(problem.b_end)};
}

// alpha a + beta b + gamma c of a limit row at x; `index` = VariableLayout::row(row.interval).
inline double rowValue(const LinearRow& row, const std::array<int, 5>& index, const double* x) {
  return row.value(x[index[0]], x[index[1]], x[index[2]], x[index[3]], x[index[4]]);
}

}  // namespace cyber::planner::topp

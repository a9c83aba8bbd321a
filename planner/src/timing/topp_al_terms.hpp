#pragma once
// Conventions shared by the augmented Lagrangian's evaluation, Hessian, multiplier update and
// multiplier estimate (internal to the planner library): one definition of each constraint's
// value at x, so L_rho, its Hessian and the updates of eqs. 30-31 cannot drift apart.

#include <array>
#include <cmath>

#include "math/second_order_cone.hpp"
#include "timing/topp_augmented_lagrangian.hpp"

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

// The affine arguments A x + b of the time cone of interval k (eq. 16) and of the speed cone of
// a node, from its b and c (eq. 17).
inline Cone3 timeCone(const VariableLayout& v, const double* x, int k) {
  const double sigma = x[v.c(k)] + x[v.c(k + 1)];
  const double d = x[v.d(k)];
  return {sigma + d, sigma - d, 2.0};
}
inline Cone3 speedCone(double b, double c) { return {b + 1.0, b - 1.0, 2.0 * c}; }

// mu / rho - (A x + b): what L_rho projects (eq. 19); mu points at the cone's three multipliers.
inline Cone3 shiftedCone(const double* mu, double inv_rho, const Cone3& u) {
  return {mu[0] * inv_rho - u.t, mu[1] * inv_rho - u.x1, mu[2] * inv_rho - u.x2};
}

// b_{k+1} - b_k - 2 ds a_k: the linear equality of interval k (ds = Problem::ds(k)), imposed
// times equalityWeight(ds).
inline double baRelation(const VariableLayout& v, const double* x, int k, double ds) {
  return x[v.b(k + 1)] - x[v.b(k)] - 2.0 * ds * x[v.a(k)];
}

// The targets of the boundary equalities, in the order of VariableLayout::boundary().
inline std::array<double, 4> boundaryTargets(const Problem& problem) {
  return {problem.b_start, problem.b_end, std::sqrt(problem.b_start), std::sqrt(problem.b_end)};
}

// alpha a + beta b + gamma c of a limit row at x; `at` = VariableLayout::row(row.interval).
inline double rowValue(const LinearRow& row, const VariableLayout::Row& at, const double* x) {
  return row.value(x[at.a], x[at.b0], x[at.b1], x[at.c0], x[at.c1]);
}

}  // namespace cyber::planner::topp

#pragma once
// Conventions shared by the augmented Lagrangian's evaluation, Hessian and multiplier estimate
// (internal to the planner library).

#include <cmath>

namespace cyber::planner::topp {

// The b-a relation is imposed as (b_{k+1} - b_k - 2 ds a_k) / sqrt(2 ds): between the rows of
// order one in a (weight 1/(2 ds)) and in b (weight 1), so that neither the curvature rho w^2 in
// b (roundoff in the gradient on fine grids) nor the weak coupling of a dominates.
inline double equalityWeight(double ds) { return 1.0 / std::sqrt(2.0 * ds); }

// The end nodes' b and c are fixed by the boundary values, which imply the speed cone, c^2 = b
// and b >= 0 there; those redundant (and, at rest, degenerate: c^2 = b has no first-order hold
// on c at 0) rows are left out at the two end nodes.
inline constexpr int kFirstFree = 1;
}  // namespace cyber::planner::topp

#pragma once
// Euclidean projection onto the second-order cone Q3 = {(t, x1, x2) : t >= |(x1, x2)|}
// (algorithm.md eq. 21): identity inside, zero inside the polar cone, otherwise the nearest point
// on the boundary.

#include <cmath>

namespace cyber::planner {

struct Cone3 {
  double t = 0.0;
  double x1 = 0.0;
  double x2 = 0.0;
};

inline Cone3 projectOntoSecondOrderCone(const Cone3& v) {
  const double norm = std::sqrt(v.x1 * v.x1 + v.x2 * v.x2);
  if (norm <= v.t) return v;
  if (norm <= -v.t) return Cone3{};
  const double half = 0.5 * (v.t + norm);
  const double scale = half / norm;  // norm > |t| >= 0 here
  return Cone3{half, scale * v.x1, scale * v.x2};
}

}  // namespace cyber::planner

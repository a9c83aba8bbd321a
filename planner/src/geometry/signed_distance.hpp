#pragma once
// Signed distance between two convex polygons (algorithm.md section 1).
//
//   value > 0: separated; the exact Euclidean distance (minimum over vertex-edge pairs, which in
//              2-D equals the QP of report eq. 7).
//   value <= 0: touching or overlapping; minus the minimum translation depth, found over the
//              edge normals of both polygons (separating axis theorem, exact for convex polygons).
//
// Both branches are 1-Lipschitz in the vertex positions and meet at 0, so the value is Lipschitz
// continuous. The witnesses give the gradient under rigid motion of A: see CollisionWorld.
//
// Polygons are read through views with size(), vertex(i) and normal(i) (outward unit normal of
// edge i, vertex i -> i+1, counter-clockwise), so a robot polygon can be transformed on the fly
// without a buffer.

#include <algorithm>
#include <cmath>
#include <limits>

#include "cyber/planner/chain.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

struct PairDistance {
  double value = std::numeric_limits<double>::infinity();
  Point2 witness_a = Point2::Zero();  // point of A (world frame; fixed to its link when A is a robot polygon)
  Point2 witness_b = Point2::Zero();  // point of B
  Point2 normal = Point2::Zero();     // unit, from A towards B: value = normal . (witness_b - witness_a)
  bool exact = false;                 // false: value is only a lower bound >= the cutoff asked for
};

// A polygon given by world-frame arrays (obstacles, tests).
struct WorldPolygonView {
  const Point2* vertices = nullptr;
  const Point2* normals = nullptr;
  int count = 0;
  [[nodiscard]] int size() const { return count; }
  [[nodiscard]] Point2 vertex(int i) const { return vertices[i]; }
  [[nodiscard]] Point2 normal(int i) const { return normals[i]; }
};

// A polygon given in a link frame, placed by that link's frame.
struct LinkPolygonView {
  const Point2* vertices_link = nullptr;
  const Point2* normals_link = nullptr;
  int count = 0;
  const LinkFrame* frame = nullptr;
  [[nodiscard]] int size() const { return count; }
  [[nodiscard]] Point2 vertex(int i) const { return frame->toWorld(vertices_link[i]); }
  [[nodiscard]] Point2 normal(int i) const { return frame->rotate(normals_link[i]); }
};

namespace detail {

// Largest gap over the edge normals of P: max_i min_j n_i . (q_j - p_i). Writes the edge and
// the vertex of Q that attain it.
template <class P, class Q>
double largestEdgeGap(const P& p, const Q& q, int* best_edge, int* best_vertex) {
  double best = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < p.size(); ++i) {
    const Point2 n = p.normal(i);
    const double offset = n.dot(p.vertex(i));
    double smallest = std::numeric_limits<double>::infinity();
    int arg = 0;
    for (int j = 0; j < q.size(); ++j) {
      const double g = n.dot(q.vertex(j)) - offset;
      if (g < smallest) {
        smallest = g;
        arg = j;
      }
    }
    if (smallest > best) {
      best = smallest;
      *best_edge = i;
      *best_vertex = arg;
    }
  }
  return best;
}

inline Point2 closestOnSegment(const Point2& x, const Point2& a, const Point2& b) {
  const Point2 e = b - a;
  const double len2 = e.squaredNorm();
  const double u = len2 > 0.0 ? std::clamp((x - a).dot(e) / len2, 0.0, 1.0) : 0.0;
  return a + u * e;
}

// Smallest distance from the vertices of P to the edges of Q; updates `out` (witness order A, B
// depends on p_is_a). A vertex behind an edge's line is skipped: when the polygons are separated,
// the closest pair has its vertex in front of the edge it is closest to (or, for a closest
// vertex of Q, in front of one of its two edges), so nothing is lost. The small tolerance keeps
// touching contacts, where that "in front" is lost in roundoff.
inline constexpr double kInFrontTolerance = 1e-9;  // m: the roundoff of a touching contact

template <class P, class Q>
void vertexEdgeDistances(const P& p, const Q& q, bool p_is_a, double* best2, PairDistance* out) {
  for (int j = 0; j < q.size(); ++j) {
    const Point2 a = q.vertex(j);
    const Point2 b = q.vertex(j + 1 == q.size() ? 0 : j + 1);
    const Point2 n = q.normal(j);
    for (int i = 0; i < p.size(); ++i) {
      const Point2 x = p.vertex(i);
      if (n.dot(x - a) < -kInFrontTolerance) continue;
      const Point2 c = closestOnSegment(x, a, b);
      const double d2 = (x - c).squaredNorm();
      if (d2 < *best2) {
        *best2 = d2;
        out->witness_a = p_is_a ? x : c;
        out->witness_b = p_is_a ? c : x;
      }
    }
  }
}

}  // namespace detail

// Signed distance of A and B. When the separating-axis gap (a lower bound of the distance) is
// already >= cutoff, returns that bound with exact = false and skips the Euclidean part.
template <class A, class B>
PairDistance signedDistance(const A& a, const B& b, double cutoff = std::numeric_limits<double>::infinity()) {
  PairDistance out;
  int edge_a = 0, vertex_b = 0, edge_b = 0, vertex_a = 0;
  const double gap_a = detail::largestEdgeGap(a, b, &edge_a, &vertex_b);
  if (gap_a >= cutoff) {
    out.value = gap_a;
    return out;
  }
  const double gap_b = detail::largestEdgeGap(b, a, &edge_b, &vertex_a);
  const double gap = std::max(gap_a, gap_b);
  if (gap >= cutoff) {
    out.value = gap;
    return out;
  }
  out.exact = true;
  if (gap <= 0.0) {
    // Overlap: the axis of least penetration. The witnesses are the deepest vertex and its
    // projection on the edge line, so value = normal . (witness_b - witness_a) still holds.
    out.value = gap;
    if (gap_a >= gap_b) {
      out.normal = a.normal(edge_a);
      out.witness_b = b.vertex(vertex_b);
      out.witness_a = out.witness_b - gap * out.normal;
    } else {
      const Point2 n_b = b.normal(edge_b);
      out.normal = -n_b;
      out.witness_a = a.vertex(vertex_a);
      out.witness_b = out.witness_a - gap * n_b;
    }
    return out;
  }
  double best2 = std::numeric_limits<double>::infinity();
  detail::vertexEdgeDistances(a, b, true, &best2, &out);
  detail::vertexEdgeDistances(b, a, false, &best2, &out);
  out.value = std::sqrt(best2);
  out.normal = (out.witness_b - out.witness_a) / out.value;
  return out;
}

}  // namespace cyber::planner

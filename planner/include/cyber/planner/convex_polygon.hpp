#pragma once
// A convex polygon with counter-clockwise vertices, validated on construction.

#include <string>
#include <vector>

#include "cyber/planner/types.hpp"

namespace cyber::planner {

class ConvexPolygon {
 public:
  ConvexPolygon() = default;

  // Accepts either orientation and stores counter-clockwise. Returns an empty optional-like
  // error text when the vertices are fewer than 3, non-finite, collinear or not convex.
  // `error` is set to the reason on failure (and the returned polygon is empty).
  static ConvexPolygon fromVertices(std::vector<Point2> vertices, std::string* error);

  // Everything the polygon covers while it slides along x from lo_m to hi_m (lo_m <= hi_m): the
  // convex hull of its two end copies (a Minkowski sum with a segment). For lo_m == hi_m, the
  // polygon moved by lo_m.
  [[nodiscard]] ConvexPolygon sweptAlongX(double lo_m, double hi_m) const;

  [[nodiscard]] const std::vector<Point2>& vertices() const { return vertices_; }
  [[nodiscard]] int size() const { return static_cast<int>(vertices_.size()); }
  [[nodiscard]] bool empty() const { return vertices_.empty(); }
  [[nodiscard]] const Point2& vertex(int i) const { return vertices_[static_cast<size_t>(i)]; }
  // Edge i runs from vertex(i) to vertex(i+1 mod n).
  [[nodiscard]] const Point2& edgeEnd(int i) const { return vertices_[static_cast<size_t>((i + 1) % size())]; }

 private:
  explicit ConvexPolygon(std::vector<Point2> ccw) : vertices_(std::move(ccw)) {}
  std::vector<Point2> vertices_;
};

}  // namespace cyber::planner

#include "cyber/planner/types.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cyber::planner {
namespace {

// Areas and turns (m^2) below these shares are roundoff of collinear points: a polygon is drawn
// in metres, so its cross products are of order one.
constexpr double kZeroArea = 1e-12;
constexpr double kStraightTurn = 1e-12;
// The turns of a convex polygon sum to 2 pi up to the roundoff of n atan2 calls; a star winds twice.
constexpr double kWindingTolerance = 1e-6;

double cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

Result<ConvexPolygon> ConvexPolygon::fromVertices(std::vector<Point2> v) {
  auto fail = [](std::string why) { return PlanError{PlanStatus::kInvalidInput, std::move(why)}; };
  const int n = static_cast<int>(v.size());
  if (n < 3) return fail("a polygon needs at least 3 vertices, got " + std::to_string(n));
  for (const Point2& p : v) {
    if (!p.allFinite()) return fail("vertex coordinates must be finite numbers");
  }
  // Signed area decides the orientation; every turn must have the same sign (strictly convex
  // up to collinear points, which we reject because they make edge normals ambiguous).
  double twice_area = 0.0;
  for (int i = 0; i < n; ++i) twice_area += cross(v[static_cast<size_t>(i)], v[static_cast<size_t>((i + 1) % n)]);
  if (std::abs(twice_area) < kZeroArea) return fail("polygon has zero area");
  if (twice_area < 0) std::reverse(v.begin(), v.end());
  for (int i = 0; i < n; ++i) {
    const Point2& a = v[static_cast<size_t>(i)];
    const Point2& b = v[static_cast<size_t>((i + 1) % n)];
    const Point2& c = v[static_cast<size_t>((i + 2) % n)];
    const double turn = cross(b - a, c - b);
    if (turn <= kStraightTurn * std::max(1.0, (b - a).squaredNorm() + (c - b).squaredNorm())) {
      return fail("polygon is not convex (or has collinear or repeated vertices) at vertex " +
                  std::to_string((i + 1) % n));
    }
  }
  // A strictly convex turn sequence can still wind twice (a star); the turns must sum to 2*pi.
  double winding = 0.0;
  for (int i = 0; i < n; ++i) {
    const Point2 e0 = v[static_cast<size_t>((i + 1) % n)] - v[static_cast<size_t>(i)];
    const Point2 e1 = v[static_cast<size_t>((i + 2) % n)] - v[static_cast<size_t>((i + 1) % n)];
    winding += std::atan2(cross(e0, e1), e0.dot(e1));
  }
  if (std::abs(winding - 2.0 * std::numbers::pi) > kWindingTolerance)
    return fail("polygon is not convex (self-intersecting)");
  return ConvexPolygon(std::move(v));
}

ConvexPolygon ConvexPolygon::sweptAlongX(double lo_m, double hi_m) const {
  std::vector<Point2> points;
  points.reserve(2 * vertices_.size());
  for (const Point2& v : vertices_) points.emplace_back(v.x() + lo_m, v.y());
  if (hi_m == lo_m) return ConvexPolygon(std::move(points));
  for (const Point2& v : vertices_) points.emplace_back(v.x() + hi_m, v.y());
  // Andrew's monotone chain, counter-clockwise, collinear points dropped.
  std::sort(points.begin(), points.end(),
            [](const Point2& a, const Point2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  std::vector<Point2> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 1]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 1]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return ConvexPolygon(std::move(hull));
}

}  // namespace cyber::planner

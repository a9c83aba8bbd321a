// ConvexPolygon::sweptAlongX against its definition: the set the polygon covers while sliding.
#include "cyber/planner/types.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace cyber::planner {
namespace {

// Whether p is inside (or on) the counter-clockwise convex polygon.
bool contains(const ConvexPolygon& polygon, const Point2& p, double tolerance) {
  for (int i = 0; i < polygon.size(); ++i) {
    const Point2 e = polygon.edgeEnd(i) - polygon.vertex(i);
    const Point2 r = p - polygon.vertex(i);
    if (e.x() * r.y() - e.y() * r.x() < -tolerance * e.norm()) return false;
  }
  return true;
}

ConvexPolygon randomPolygon(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 3 + static_cast<int>(u(rng) * 6);
  const Point2 centre(4 * u(rng) - 2, 4 * u(rng) - 2);
  // Points on an ellipse in increasing angle: always convex.
  const Point2 radii(0.1 + u(rng), 0.1 + u(rng));
  std::vector<Point2> v;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * M_PI * (i + 0.5 * u(rng)) / n;
    v.push_back(centre + Point2(radii.x() * std::cos(angle), radii.y() * std::sin(angle)));
  }
  auto polygon = ConvexPolygon::fromVertices(v);
  return polygon ? std::move(polygon).value() : ConvexPolygon{};
}

TEST(ConvexPolygon, ASweepIsConvexAndCoversExactlyWhereThePolygonSlides) {
  std::mt19937 rng(24);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const ConvexPolygon p = randomPolygon(rng);
    if (p.empty()) continue;
    const double lo = u(rng) - 0.5, hi = lo + (trial % 5 == 0 ? 0.0 : u(rng));
    const ConvexPolygon swept = p.sweptAlongX(lo, hi);
    const auto valid = ConvexPolygon::fromVertices(swept.vertices());
    ASSERT_TRUE(valid.ok()) << valid.error().message;
    // Every copy along the way is inside.
    for (int k = 0; k <= 10; ++k) {
      const double dx = lo + (hi - lo) * k / 10.0;
      for (const Point2& v : p.vertices()) EXPECT_TRUE(contains(swept, v + Point2(dx, 0.0), 1e-12));
    }
    // And nothing else: each hull vertex is a vertex of an end copy.
    for (const Point2& h : swept.vertices()) {
      bool found = false;
      for (const Point2& v : p.vertices()) {
        found = found || (h - (v + Point2(lo, 0.0))).norm() < 1e-12 || (h - (v + Point2(hi, 0.0))).norm() < 1e-12;
      }
      EXPECT_TRUE(found) << h.transpose();
    }
    ++checked;
  }
  EXPECT_GT(checked, 250);
}

}  // namespace
}  // namespace cyber::planner

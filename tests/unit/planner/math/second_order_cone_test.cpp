// The projection onto Q3 (algorithm.md eq. 21) against its defining properties (in the cone,
// idempotent, Moreau's decomposition) and against brute force: no point of the cone is nearer.

#include "math/second_order_cone.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

namespace cyber::planner {
namespace {

double distance(const Cone3& a, const Cone3& b) {
  return std::sqrt((a.t - b.t) * (a.t - b.t) + (a.x1 - b.x1) * (a.x1 - b.x1) + (a.x2 - b.x2) * (a.x2 - b.x2));
}

TEST(SecondOrderCone, ProjectionHasTheDefiningProperties) {
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0.0, 2.0);
  auto norm = [](const Cone3& c) { return std::sqrt(c.x1 * c.x1 + c.x2 * c.x2); };
  for (int i = 0; i < 1000; ++i) {
    const Cone3 v{g(rng), g(rng), g(rng)};
    const Cone3 p = projectOntoSecondOrderCone(v);
    EXPECT_LE(norm(p), p.t + 1e-12);  // in the cone
    const Cone3 again = projectOntoSecondOrderCone(p);
    EXPECT_NEAR(again.t, p.t, 1e-12);  // idempotent
    // Moreau: v = P(v) - P(-v) with P(v) orthogonal to P(-v).
    const Cone3 m = projectOntoSecondOrderCone({-v.t, -v.x1, -v.x2});
    EXPECT_NEAR(p.t - m.t, v.t, 1e-12);
    EXPECT_NEAR(p.x1 - m.x1, v.x1, 1e-12);
    EXPECT_NEAR(p.x2 - m.x2, v.x2, 1e-12);
    EXPECT_NEAR(p.t * m.t + p.x1 * m.x1 + p.x2 * m.x2, 0.0, 1e-9);
  }
  const Cone3 inside = projectOntoSecondOrderCone({2.0, 1.0, 1.0});
  EXPECT_EQ(inside.t, 2.0);
  const Cone3 polar = projectOntoSecondOrderCone({-2.0, 1.0, 1.0});
  EXPECT_EQ(polar.t, 0.0);
  EXPECT_EQ(polar.x1, 0.0);
}

// Seeded points against a few thousand seeded points of the cone each: none is nearer than the
// projection.
TEST(SecondOrderCone, NoPointOfTheConeIsNearerThanTheProjection) {
  std::mt19937 rng(29);
  std::normal_distribution<double> g(0.0, 2.0);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi), radius(0.0, 6.0), slack(0.0, 1.0);
  for (int i = 0; i < 100; ++i) {
    const Cone3 v{g(rng), g(rng), g(rng)};
    const double projected = distance(v, projectOntoSecondOrderCone(v));
    for (int j = 0; j < 2000; ++j) {
      const double r = radius(rng), phi = angle(rng);
      // On the boundary half the time: that is where the nearest point of an outside v lies.
      const Cone3 c{r + (j % 2 == 0 ? 0.0 : slack(rng)), r * std::cos(phi), r * std::sin(phi)};
      ASSERT_GE(distance(v, c), projected - 1e-12) << "point " << i << ", candidate " << j;
    }
  }
}

}  // namespace
}  // namespace cyber::planner

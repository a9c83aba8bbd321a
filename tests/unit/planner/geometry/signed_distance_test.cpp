// Polygon-polygon signed distance against brute force: dense boundary sampling when separated,
// dense direction sampling of the minimum translation when overlapping.

#include "geometry/signed_distance.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace cyber::planner {
namespace {

struct TestPolygon {
  std::vector<Point2> vertices;  // counter-clockwise
  std::vector<Point2> normals;
  [[nodiscard]] WorldPolygonView view() const {
    return {vertices.data(), normals.data(), static_cast<int>(vertices.size())};
  }
};

TestPolygon withNormals(std::vector<Point2> v) {
  TestPolygon p;
  p.vertices = std::move(v);
  for (size_t i = 0; i < p.vertices.size(); ++i) {
    const Point2 e = p.vertices[(i + 1) % p.vertices.size()] - p.vertices[i];
    p.normals.emplace_back(Point2(e.y(), -e.x()).normalized());
  }
  return p;
}

// Convex polygon: points on an ellipse at sorted random angles, rotated and placed at centre.
TestPolygon randomPolygon(std::mt19937& rng, const Point2& centre) {
  std::uniform_int_distribution<int> count(3, 8);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int n = count(rng);
  std::vector<double> angles;
  for (int i = 0; i < n; ++i) angles.push_back(2.0 * std::numbers::pi * unit(rng));
  std::sort(angles.begin(), angles.end());
  const double rx = 0.05 + 0.3 * unit(rng);
  const double ry = 0.05 + 0.3 * unit(rng);
  const double rot = 2.0 * std::numbers::pi * unit(rng);
  std::vector<Point2> v;
  for (double a : angles) {
    const Point2 p(rx * std::cos(a), ry * std::sin(a));
    const Point2 r(std::cos(rot) * p.x() - std::sin(rot) * p.y(), std::sin(rot) * p.x() + std::cos(rot) * p.y());
    const Point2 candidate = centre + r;
    // Near-duplicate angles make degenerate edges; skip them.
    if (!v.empty() && (candidate - v.back()).norm() < 1e-3) continue;
    v.push_back(candidate);
  }
  if (v.size() >= 3 && (v.front() - v.back()).norm() < 1e-3) v.pop_back();
  if (v.size() < 3) return randomPolygon(rng, centre);
  return withNormals(std::move(v));
}

double pointSegmentDistance(const Point2& x, const Point2& a, const Point2& b) {
  const Point2 e = b - a;
  const double u = std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (x - (a + u * e)).norm();
}

std::vector<Point2> sampleBoundary(const TestPolygon& p, double spacing) {
  std::vector<Point2> out;
  for (size_t i = 0; i < p.vertices.size(); ++i) {
    const Point2& a = p.vertices[i];
    const Point2& b = p.vertices[(i + 1) % p.vertices.size()];
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing)));
    for (int k = 0; k < steps; ++k) out.push_back(a + (b - a) * (static_cast<double>(k) / steps));
  }
  return out;
}

bool contains(const TestPolygon& p, const Point2& x) {
  for (size_t i = 0; i < p.vertices.size(); ++i) {
    if (p.normals[i].dot(x - p.vertices[i]) > 0.0) return false;
  }
  return true;
}

// Boundaries cross or one contains the other: brute-force overlap test on sampled boundaries.
bool overlapBySampling(const TestPolygon& a, const TestPolygon& b) {
  for (const Point2& x : sampleBoundary(a, 1e-3)) {
    if (contains(b, x)) return true;
  }
  for (const Point2& x : sampleBoundary(b, 1e-3)) {
    if (contains(a, x)) return true;
  }
  return false;
}

// Minimum translation that separates A and B, over densely sampled directions: for direction u,
// B must move by max_a(u.a) - min_b(u.b) along u.
double minimumTranslationBySampling(const TestPolygon& a, const TestPolygon& b, int directions) {
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < directions; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / directions;
    const Point2 u(std::cos(angle), std::sin(angle));
    double max_a = -std::numeric_limits<double>::infinity();
    double min_b = std::numeric_limits<double>::infinity();
    for (const Point2& x : a.vertices) max_a = std::max(max_a, u.dot(x));
    for (const Point2& x : b.vertices) min_b = std::min(min_b, u.dot(x));
    best = std::min(best, max_a - min_b);
  }
  return best;
}

TEST(SignedDistance, SeparatedPolygonsMatchDenseBoundarySampling) {
  std::mt19937 rng(20250101);
  std::uniform_real_distribution<double> offset(-1.0, 1.0);
  int separated = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const TestPolygon a = randomPolygon(rng, Point2::Zero());
    const TestPolygon b = randomPolygon(rng, Point2(offset(rng), offset(rng)));
    if (overlapBySampling(a, b)) continue;
    ++separated;
    const PairDistance d = signedDistance(a.view(), b.view());
    ASSERT_TRUE(d.exact);
    // Sampled points of A against the exact edges of B (and vice versa): never below d, and
    // within the sampling spacing of it.
    const double spacing = 5e-4;
    double brute = std::numeric_limits<double>::infinity();
    for (const auto& [p, q] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
      for (const Point2& x : sampleBoundary(*p, spacing)) {
        for (size_t i = 0; i < q->vertices.size(); ++i) {
          brute = std::min(brute, pointSegmentDistance(x, q->vertices[i], q->vertices[(i + 1) % q->vertices.size()]));
        }
      }
    }
    EXPECT_GT(d.value, 0.0);
    EXPECT_GE(brute, d.value - 1e-12) << "trial " << trial;
    EXPECT_LE(brute, d.value + spacing) << "trial " << trial;
    // Witnesses lie on the polygons and realise the distance.
    EXPECT_NEAR((d.witness_b - d.witness_a).norm(), d.value, 1e-12);
    EXPECT_NEAR(d.normal.dot(d.witness_b - d.witness_a), d.value, 1e-12);
  }
  EXPECT_GT(separated, 100);
}

TEST(SignedDistance, OverlappingPolygonsGiveMinusTheMinimumTranslation) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> offset(-0.3, 0.3);
  int overlapping = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const TestPolygon a = randomPolygon(rng, Point2::Zero());
    const TestPolygon b = randomPolygon(rng, Point2(offset(rng), offset(rng)));
    if (!overlapBySampling(a, b)) continue;
    ++overlapping;
    const PairDistance d = signedDistance(a.view(), b.view());
    ASSERT_TRUE(d.exact);
    EXPECT_LE(d.value, 0.0);
    const int directions = 20000;
    const double brute = minimumTranslationBySampling(a, b, directions);
    // The sampled directions include no edge normal exactly, so brute is slightly above the depth.
    EXPECT_GE(brute, -d.value - 1e-12) << "trial " << trial;
    EXPECT_LE(brute, -d.value + 2.0 * std::numbers::pi / directions) << "trial " << trial;
    // Translating B by the depth along the normal leaves the two just touching.
    TestPolygon moved = b;
    for (Point2& v : moved.vertices) v -= d.value * d.normal;
    const PairDistance touching = signedDistance(a.view(), moved.view());
    EXPECT_NEAR(touching.value, 0.0, 1e-9) << "trial " << trial;
    EXPECT_NEAR(d.normal.dot(d.witness_b - d.witness_a), d.value, 1e-12);
  }
  EXPECT_GT(overlapping, 100);
}

TEST(SignedDistance, IsOneLipschitzUnderTranslation) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> offset(-0.6, 0.6);
  std::uniform_real_distribution<double> small(-0.02, 0.02);
  for (int trial = 0; trial < 2000; ++trial) {
    const TestPolygon a = randomPolygon(rng, Point2::Zero());
    const TestPolygon b = randomPolygon(rng, Point2(offset(rng), offset(rng)));
    TestPolygon moved = b;
    const Point2 shift(small(rng), small(rng));
    for (Point2& v : moved.vertices) v += shift;
    const double d0 = signedDistance(a.view(), b.view()).value;
    const double d1 = signedDistance(a.view(), moved.view()).value;
    EXPECT_LE(std::abs(d1 - d0), shift.norm() + 1e-12) << "trial " << trial;
  }
}

TEST(SignedDistance, CutoffReturnsALowerBoundWithoutWitnesses) {
  const TestPolygon a = withNormals({Point2(0, 0), Point2(1, 0), Point2(1, 1), Point2(0, 1)});
  const TestPolygon b = withNormals({Point2(3, 0), Point2(4, 0), Point2(4, 1), Point2(3, 1)});
  const PairDistance exact = signedDistance(a.view(), b.view());
  EXPECT_DOUBLE_EQ(exact.value, 2.0);
  const PairDistance bounded = signedDistance(a.view(), b.view(), 1.0);
  EXPECT_FALSE(bounded.exact);
  EXPECT_GE(bounded.value, 1.0);
  EXPECT_LE(bounded.value, 2.0);
  const PairDistance below = signedDistance(a.view(), b.view(), 2.5);
  EXPECT_TRUE(below.exact);
  EXPECT_DOUBLE_EQ(below.value, 2.0);
}

TEST(SignedDistance, CornerToCornerUsesTheEuclideanDistanceNotTheAxisGap) {
  // Diagonal corners: the separating-axis gap is 1, the true distance sqrt(2).
  const TestPolygon a = withNormals({Point2(0, 0), Point2(1, 0), Point2(1, 1), Point2(0, 1)});
  const TestPolygon b = withNormals({Point2(2, 2), Point2(3, 2), Point2(3, 3), Point2(2, 3)});
  const PairDistance d = signedDistance(a.view(), b.view());
  EXPECT_NEAR(d.value, std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(d.witness_a.x(), 1.0, 1e-15);
  EXPECT_NEAR(d.witness_b.y(), 2.0, 1e-15);
}

}  // namespace
}  // namespace cyber::planner

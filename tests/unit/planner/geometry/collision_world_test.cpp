// d(q) for the reference robot: pose transform, brute-force agreement, cutoff bounds, held pieces
// only adding geometry, and the gradient against central differences.

#include "cyber/planner/collision_world.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "geometry/signed_distance.hpp"
#include "reference_model.hpp"

namespace cyber::planner {
namespace {

const RobotModel& model() { return test::referenceModel(); }
const Scene& scene() { return model().scenes.front(); }

JointVector randomPose(std::mt19937& rng) {
  std::uniform_real_distribution<double> t(model().range(0).min, model().range(0).max);
  std::uniform_real_distribution<double> th(model().range(1).min, model().range(1).max);
  const double t_m = t(rng);  // drawn in sequence: argument order is unspecified
  return JointVector{{t_m, th(rng)}};
}

std::vector<Point2> normalsOf(const std::vector<Point2>& v) {
  std::vector<Point2> n;
  for (size_t i = 0; i < v.size(); ++i) {
    const Point2 e = v[(i + 1) % v.size()] - v[i];
    n.emplace_back(Point2(e.y(), -e.x()).normalized());
  }
  return n;
}

// Every robot polygon moved to the world by hand (rotation matrices, not LinkFrame), every pair
// computed without pruning.
double bruteForceDistance(const JointVector& q, HeldPieces pieces) {
  const ChainJoint& rail = model().joints[0];
  const Point2 pivot = rail.origin_m + q[0] * Point2(std::cos(rail.axis_rad), std::sin(rail.axis_rad));
  std::vector<const ConvexPolygon*> robot;
  for (const LinkGeometry& link : model().links) {
    for (const auto& p : link.polygons) robot.push_back(&p);
  }
  for (size_t i = 0; i < model().pieces.size(); ++i) {
    if (!pieces.holds(static_cast<int>(i))) continue;
    for (const auto& p : model().pieces[i].polygons) robot.push_back(&p);
  }
  double best = std::numeric_limits<double>::infinity();
  for (const ConvexPolygon* polygon : robot) {
    std::vector<Point2> world;
    for (const Point2& p : polygon->vertices()) {
      world.emplace_back(pivot.x() + std::cos(q[1]) * p.x() - std::sin(q[1]) * p.y(),
                         pivot.y() + std::sin(q[1]) * p.x() + std::cos(q[1]) * p.y());
    }
    const std::vector<Point2> world_normals = normalsOf(world);
    for (const auto* list : {&scene().obstacles, &scene().fixed}) {
      for (const NamedPolygon& obstacle : *list) {
        const std::vector<Point2>& ov = obstacle.polygon.vertices();
        const std::vector<Point2> on = normalsOf(ov);
        const PairDistance d =
            signedDistance(WorldPolygonView{world.data(), world_normals.data(), static_cast<int>(world.size())},
                           WorldPolygonView{ov.data(), on.data(), static_cast<int>(ov.size())});
        best = std::min(best, d.value);
      }
    }
  }
  return best;
}

TEST(CollisionWorld, AgreesWithBruteForceOverAllPairs) {
  std::mt19937 rng(11);
  for (int set = 0; set < model().pieceSetCount(); ++set) {
    const HeldPieces pieces = HeldPieces::fromIndex(set);
    const CollisionWorld world(model(), scene(), pieces);
    for (int trial = 0; trial < 500; ++trial) {
      const JointVector q = randomPose(rng);
      const SignedDistance d = world.distance(q);
      ASSERT_TRUE(d.exact);
      EXPECT_NEAR(d.value, bruteForceDistance(q, pieces), 1e-12) << "set " << set << " q " << q.transpose();
    }
  }
}

TEST(CollisionWorld, CutoffGivesExactValuesBelowItAndLowerBoundsAbove) {
  const CollisionWorld world(model(), scene(), test::referencePieces("coral+algae"));
  std::mt19937 rng(12);
  int bounded = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const JointVector q = randomPose(rng);
    const double exact = world.distance(q).value;
    for (double cutoff : {-0.05, 0.0, 0.03, 0.1, 0.4}) {
      const SignedDistance d = world.distance(q, cutoff);
      if (exact < cutoff) {
        EXPECT_TRUE(d.exact);
        EXPECT_DOUBLE_EQ(d.value, exact);
      } else {
        ++bounded;
        EXPECT_GE(d.value, cutoff);
        EXPECT_LE(d.value, exact + 1e-15);
      }
    }
  }
  EXPECT_GT(bounded, 1000);
}

TEST(CollisionWorld, HeldPiecesOnlyAddGeometry) {
  std::vector<CollisionWorld> worlds;
  for (int set = 0; set < model().pieceSetCount(); ++set)
    worlds.emplace_back(model(), scene(), HeldPieces::fromIndex(set));
  EXPECT_EQ(worlds[0].robotPolygonCount(), 1);
  EXPECT_EQ(worlds[3].robotPolygonCount(), 3);
  std::mt19937 rng(13);
  int strictly_closer = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const JointVector q = randomPose(rng);
    const double none = worlds[0].distance(q).value;
    const double coral = worlds[1].distance(q).value;
    const double algae = worlds[2].distance(q).value;
    const double both = worlds[3].distance(q).value;
    EXPECT_LE(coral, none);
    EXPECT_LE(algae, none);
    EXPECT_LE(both, std::min(coral, algae));
    if (both < none - 1e-6) ++strictly_closer;
  }
  EXPECT_GT(strictly_closer, 100);  // the pieces matter, they are not ignored
  EXPECT_GT(worlds[3].pointSpeedBound()[1], worlds[0].pointSpeedBound()[1]);
}

TEST(CollisionWorld, GradientMatchesCentralDifferences) {
  std::mt19937 rng(14);
  int checked = 0, penetrating = 0;
  for (int set = 0; set < model().pieceSetCount(); ++set) {
    const CollisionWorld world(model(), scene(), HeldPieces::fromIndex(set));
    for (int trial = 0; trial < 400; ++trial) {
      const JointVector q = randomPose(rng);
      const SignedDistance d = world.distance(q);
      const double h = 1e-7;
      JointVector central, forward, backward;
      for (int j = 0; j < 2; ++j) {
        JointVector dq = JointVector::Zero(2);
        dq[j] = h;
        const double plus = world.distance(q + dq).value;
        const double minus = world.distance(q - dq).value;
        central[j] = (plus - minus) / (2 * h);
        forward[j] = (plus - d.value) / h;
        backward[j] = (d.value - minus) / h;
      }
      // Skip the measure-zero kinks (a switch of the closest pair or feature inside the step).
      if ((forward - backward).norm() > 1e-4) continue;
      ++checked;
      if (d.value < 0) ++penetrating;
      EXPECT_NEAR((d.gradient - central).norm(), 0.0, 1e-5 * std::max(1.0, central.norm()))
          << "set " << set << " q " << q.transpose() << " d " << d.value << " grad " << d.gradient.transpose() << " fd "
          << central.transpose();
    }
  }
  EXPECT_GT(checked, 1400);
  EXPECT_GT(penetrating, 50);
}

TEST(CollisionWorld, EmptySceneIsInfinitelyFarAway) {
  const CollisionWorld world(model(), Scene{"empty", {}, {}, {}}, HeldPieces{});
  const SignedDistance d = world.distance(JointVector{{1.0, 1.0}});
  EXPECT_FALSE(d.exact);
  EXPECT_TRUE(std::isinf(d.value));
}

}  // namespace
}  // namespace cyber::planner

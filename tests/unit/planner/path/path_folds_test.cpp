// Where a path folds back on itself: straight and gently turning paths do not, a path that
// reverses does, and so does a hairpin in two joints; a fold between two samples is not missed.

#include "path/path_folds.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "path/cubic_spline_path.hpp"

namespace cyber::planner {
namespace {

CubicSplinePath spline(const std::vector<JointVector>& waypoints) {
  const JointVector metric = JointVector::Ones(waypoints.front().size());
  return CubicSplinePath::through(waypoints, metric).value();
}

constexpr double kSpacing = 0.0125;

TEST(PathFolds, AStraightPathDoesNotTurn) {
  const CubicSplinePath path = spline({JointVector{{0.1, 0.2}}, JointVector{{0.5, 0.4}}, JointVector{{0.9, 0.6}}});
  EXPECT_NEAR(sharpestTurnCosine(path, kSpacing), 1.0, 1e-12);
}

TEST(PathFolds, AZeroLengthPathCountsAsStraight) {
  const CubicSplinePath path = spline({JointVector{{0.3}}});
  EXPECT_EQ(sharpestTurnCosine(path, kSpacing), 1.0);
}

// One joint that first moves down, then up past where it started: its velocity must reverse.
TEST(PathFolds, OneJointThatReversesFolds) {
  const CubicSplinePath path =
      spline({JointVector{{0.30}}, JointVector{{0.20}}, JointVector{{0.15}}, JointVector{{0.25}}, JointVector{{0.90}}});
  EXPECT_LT(sharpestTurnCosine(path, kSpacing), -0.99);
}

// A corner of a right angle, smoothed by the spline over its knots 0.05 apart, is no fold, nor is a
// U-turn 0.01 wide (the tangent turns through it at a finite speed); out and straight back is.
TEST(PathFolds, ARightAngleOrAUTurnIsNoFoldAndStraightBackIs) {
  const CubicSplinePath corner = spline({JointVector{{0.0, 0.0}}, JointVector{{0.05, 0.0}}, JointVector{{0.1, 0.0}},
                                         JointVector{{0.1, 0.05}}, JointVector{{0.1, 0.1}}});
  EXPECT_GT(sharpestTurnCosine(corner, kSpacing), 0.0);
  const CubicSplinePath u_turn = spline({JointVector{{0.0, 0.0}}, JointVector{{0.05, 0.0}}, JointVector{{0.1, 0.0}},
                                         JointVector{{0.05, 0.01}}, JointVector{{0.0, 0.01}}});
  EXPECT_GT(sharpestTurnCosine(u_turn, kSpacing), 0.0);
  const CubicSplinePath back = spline({JointVector{{0.0, 0.0}}, JointVector{{0.05, 0.0}}, JointVector{{0.1, 0.0}},
                                       JointVector{{0.05, 0.0}}, JointVector{{0.0, 0.0}}});
  EXPECT_LT(sharpestTurnCosine(back, kSpacing), -0.99);
}

// Sampled `spacing` apart, a reversal between two samples still shows: the tangents on either side
// of it point opposite ways, whatever the phase of the samples against it.
TEST(PathFolds, AFoldBetweenSamplesIsFoundAtEverySpacing) {
  const CubicSplinePath path =
      spline({JointVector{{0.30}}, JointVector{{0.20}}, JointVector{{0.15}}, JointVector{{0.25}}, JointVector{{0.90}}});
  for (double spacing = 0.001; spacing <= 0.05; spacing *= 1.3) {
    EXPECT_LT(sharpestTurnCosine(path, spacing), -0.9) << spacing;
  }
}

}  // namespace
}  // namespace cyber::planner

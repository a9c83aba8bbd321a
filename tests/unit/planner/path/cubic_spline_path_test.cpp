// The cubic spline path: interpolation, C^2 continuity at the knots, end conditions, derivatives
// against differences, exact segment bounds, and no allocation in at().

#include "path/cubic_spline_path.hpp"

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"

namespace cyber::planner {
namespace {

const JointVector kMetric{{1.0, 0.1}};

double weightedNorm(const JointVector& v) { return std::sqrt(kMetric[0] * v[0] * v[0] + kMetric[1] * v[1] * v[1]); }

std::vector<JointVector> randomWaypoints(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> step_t(-0.1, 0.1), step_th(-0.4, 0.4);
  std::vector<JointVector> w{JointVector{{1.0, 3.0}}};
  for (int k = 1; k < count; ++k) {
    const double dt = step_t(rng);  // drawn in sequence: argument order is unspecified
    w.push_back(w.back() + JointVector{{dt, step_th(rng)}});
  }
  return w;
}

TEST(CubicSplinePath, InterpolatesTheWaypointsAtWeightedChordLengthKnots) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 50; ++trial) {
    const auto w = randomWaypoints(rng, 2 + trial % 12);
    const auto path = CubicSplinePath::through(w, kMetric);
    ASSERT_TRUE(path.ok());
    const auto& knots = path.value().knots();
    ASSERT_EQ(knots.size(), w.size());
    EXPECT_EQ(knots.front(), 0.0);
    for (size_t k = 0; k < w.size(); ++k) {
      if (k > 0) {
        EXPECT_NEAR(knots[k] - knots[k - 1], weightedNorm(w[k] - w[k - 1]), 1e-12);
      }
      EXPECT_NEAR((path.value().at(knots[k]).q - w[k]).norm(), 0.0, 1e-12);
    }
    EXPECT_DOUBLE_EQ(path.value().length(), knots.back());
  }
}

TEST(CubicSplinePath, IsTwiceContinuouslyDifferentiableAtTheKnots) {
  std::mt19937 rng(2);
  for (int trial = 0; trial < 50; ++trial) {
    const auto w = randomWaypoints(rng, 3 + trial % 10);
    const JointVector v0 = trial % 2 == 0 ? JointVector::Zero(2) : JointVector{{0.5, -2.0}};
    const auto path = CubicSplinePath::through(w, kMetric, v0);
    ASSERT_TRUE(path.ok());
    const auto& knots = path.value().knots();
    // One-sided limits: the left segment's end and the right segment's start, a hair apart.
    const double eps = 1e-11;
    for (size_t k = 1; k + 1 < knots.size(); ++k) {
      const PathPoint left = path.value().at(knots[k] - eps);
      const PathPoint right = path.value().at(knots[k]);
      const double scale = 1.0 + right.d2q_ds2.norm();
      EXPECT_NEAR((left.q - right.q).norm(), 0.0, 1e-9);
      EXPECT_NEAR((left.dq_ds - right.dq_ds).norm(), 0.0, 1e-8 * scale);
      EXPECT_NEAR((left.d2q_ds2 - right.d2q_ds2).norm(), 0.0, 1e-6 * scale) << "knot " << k;
    }
  }
}

TEST(CubicSplinePath, NaturalEndsOrAClampedUnitSpeedStart) {
  std::mt19937 rng(3);
  const auto w = randomWaypoints(rng, 8);
  const auto natural = CubicSplinePath::through(w, kMetric);
  ASSERT_TRUE(natural.ok());
  EXPECT_NEAR(natural.value().at(0.0).d2q_ds2.norm(), 0.0, 1e-9);
  EXPECT_NEAR(natural.value().at(natural.value().length()).d2q_ds2.norm(), 0.0, 1e-9);

  const JointVector v0{{1.5, -4.0}};  // m/s, rad/s
  const auto clamped = CubicSplinePath::through(w, kMetric, v0);
  ASSERT_TRUE(clamped.ok());
  const PathPoint start = clamped.value().at(0.0);
  EXPECT_NEAR((start.dq_ds - v0 / weightedNorm(v0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(weightedNorm(start.dq_ds), 1.0, 1e-12);
  EXPECT_NEAR(clamped.value().at(clamped.value().length()).d2q_ds2.norm(), 0.0, 1e-9);
}

TEST(CubicSplinePath, DerivativesMatchCentralDifferences) {
  std::mt19937 rng(4);
  const auto w = randomWaypoints(rng, 12);
  const auto path = CubicSplinePath::through(w, kMetric, JointVector{{0.2, 1.0}});
  ASSERT_TRUE(path.ok());
  std::uniform_real_distribution<double> where(1e-3, path.value().length() - 1e-3);
  const double h = 1e-6;
  for (int trial = 0; trial < 200; ++trial) {
    const double s = where(rng);
    const PathPoint p = path.value().at(s);
    const PathPoint plus = path.value().at(s + h);
    const PathPoint minus = path.value().at(s - h);
    EXPECT_NEAR((p.dq_ds - (plus.q - minus.q) / (2 * h)).norm(), 0.0, 1e-6);
    EXPECT_NEAR((p.d2q_ds2 - (plus.dq_ds - minus.dq_ds) / (2 * h)).norm(), 0.0, 1e-4);
  }
}

TEST(CubicSplinePath, ChordLengthParameterIsCloseToUnitSpeed) {
  // Finely sampled smooth data: the spline's Sigma-speed stays near 1 (s is an arc length).
  std::vector<JointVector> w;
  for (int k = 0; k <= 40; ++k) w.push_back(JointVector{{0.5 + 0.5 * std::sin(k * 0.05), 1.0 + 2.0 * k * 0.05}});
  const auto path = CubicSplinePath::through(w, kMetric);
  ASSERT_TRUE(path.ok());
  for (double s = 0.0; s <= path.value().length(); s += 0.01) {
    EXPECT_NEAR(weightedNorm(path.value().at(s).dq_ds), 1.0, 2e-3) << s;
  }
}

TEST(CubicSplinePath, TwoPointsGiveAStraightLine) {
  const std::vector<JointVector> w{JointVector{{0.2, 1.57}}, JointVector{{1.9, 5.0}}};
  const auto path = CubicSplinePath::through(w, kMetric);
  ASSERT_TRUE(path.ok());
  const double length = weightedNorm(w[1] - w[0]);
  EXPECT_NEAR(path.value().length(), length, 1e-15);
  for (double f : {0.0, 0.3, 0.77, 1.0}) {
    const PathPoint p = path.value().at(f * length);
    EXPECT_NEAR((p.q - (w[0] + f * (w[1] - w[0]))).norm(), 0.0, 1e-12);
    EXPECT_NEAR((p.dq_ds - (w[1] - w[0]) / length).norm(), 0.0, 1e-12);
    EXPECT_NEAR(p.d2q_ds2.norm(), 0.0, 1e-12);
  }
}

TEST(CubicSplinePath, ZeroLengthPathHoldsThePoseWithZeroDerivatives) {
  const std::vector<JointVector> w{JointVector{{0.5, 2.0}}, JointVector{{0.5, 2.0}}};
  const auto path = CubicSplinePath::through(w, kMetric);
  ASSERT_TRUE(path.ok());
  EXPECT_EQ(path.value().length(), 0.0);
  EXPECT_EQ(path.value().segmentCount(), 0);
  for (double s : {-1.0, 0.0, 3.0}) {
    const PathPoint p = path.value().at(s);
    EXPECT_EQ(p.q, w[0]);
    EXPECT_EQ(p.dq_ds, JointVector::Zero(2));
    EXPECT_EQ(p.d2q_ds2, JointVector::Zero(2));
  }
}

TEST(CubicSplinePath, RepeatedWaypointsAreMergedAndTheGoalKeptExactly) {
  const std::vector<JointVector> w{JointVector{{0.0, 0.0}}, JointVector{{0.0, 0.0}}, JointVector{{0.5, 1.0}},
                                   JointVector{{1.0, 1.0}}, JointVector{{1.0, 1.0 + 1e-12}}};
  const auto path = CubicSplinePath::through(w, kMetric);
  ASSERT_TRUE(path.ok());
  EXPECT_EQ(path.value().points().size(), 3U);
  EXPECT_EQ(path.value().at(path.value().length()).q, w.back());
}

TEST(CubicSplinePath, ParameterOutsideTheRangeIsClamped) {
  const std::vector<JointVector> w{JointVector{{0.0, 0.0}}, JointVector{{0.5, 1.0}}, JointVector{{1.0, 0.0}}};
  const auto path = CubicSplinePath::through(w, kMetric);
  ASSERT_TRUE(path.ok());
  EXPECT_EQ(path.value().at(-5.0).q, w.front());
  EXPECT_NEAR((path.value().at(1e9).q - w.back()).norm(), 0.0, 1e-12);
}

TEST(CubicSplinePath, BadInputIsATypedError) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<JointVector> empty;
  EXPECT_EQ(CubicSplinePath::through(empty, kMetric).status(), PlanStatus::kInvalidInput);
  const std::vector<JointVector> bad{JointVector{{0.0, 0.0}}, JointVector{{nan, 1.0}}};
  EXPECT_EQ(CubicSplinePath::through(bad, kMetric).status(), PlanStatus::kInvalidInput);
  const std::vector<JointVector> good{JointVector{{0.0, 0.0}}, JointVector{{1.0, 1.0}}};
  EXPECT_EQ(CubicSplinePath::through(good, (JointVector{{1.0, 0.0}})).status(), PlanStatus::kInvalidInput);
  EXPECT_EQ(CubicSplinePath::through(good, kMetric, (JointVector{{nan, 0.0}})).status(), PlanStatus::kInvalidInput);
}

TEST(CubicSplinePath, SegmentBoundsAreExact) {
  std::mt19937 rng(5);
  const auto w = randomWaypoints(rng, 10);
  const auto path = CubicSplinePath::through(w, kMetric, JointVector{{1.0, 1.0}});
  ASSERT_TRUE(path.ok());
  const auto& knots = path.value().knots();
  for (int k = 0; k < path.value().segmentCount(); ++k) {
    const auto bounds = path.value().segmentBounds(k);
    JointVector lo = JointVector::Constant(2, 1e9), hi = JointVector::Constant(2, -1e9), speed = JointVector::Zero(2);
    for (int i = 0; i <= 2000; ++i) {
      const double s = knots[static_cast<size_t>(k)] +
                       (knots[static_cast<size_t>(k) + 1] - knots[static_cast<size_t>(k)]) * i / 2000.0;
      const PathPoint p = path.value().at(s);
      lo = lo.cwiseMin(p.q);
      hi = hi.cwiseMax(p.q);
      speed = speed.cwiseMax(p.dq_ds.cwiseAbs());
    }
    for (int j = 0; j < 2; ++j) {
      EXPECT_LE(bounds.q_min[j], lo[j] + 1e-12);
      EXPECT_GE(bounds.q_min[j], lo[j] - 1e-6);
      EXPECT_GE(bounds.q_max[j], hi[j] - 1e-12);
      EXPECT_LE(bounds.q_max[j], hi[j] + 1e-6);
      EXPECT_GE(bounds.abs_dq_max[j], speed[j] - 1e-12);
      EXPECT_LE(bounds.abs_dq_max[j], speed[j] + 1e-5);
    }
  }
}

// A straight move to or from a pose on a joint limit (the shipped pivot-telescope's STOW and
// REACH_UP lie on the telescope's 0 and 0.9 m): the polynomial evaluated at the segment's end was
// a few ulp outside the limit, and the limit check refused the straight path.
TEST(CubicSplinePath, AStraightMoveToAPoseOnALimitStaysExactlyWithinItsEnds) {
  const JointVector metric{{1.0, 0.4}};
  const std::vector<std::pair<JointVector, JointVector>> moves{
      {JointVector{{1.45, 0.0}}, JointVector{{1.3, 0.9}}},     {JointVector{{0.524, 0.879}}, JointVector{{1.45, 0.0}}},
      {JointVector{{2.6, 0.2}}, JointVector{{1.45, 0.0}}},     {JointVector{{1.3, 0.9}}, JointVector{{1.45, 0.0}}},
      {JointVector{{1.45, 0.0}}, JointVector{{0.524, 0.879}}}, {JointVector{{1.45, 0.0}}, JointVector{{2.6, 0.2}}}};
  for (const auto& [from, to] : moves) {
    const std::vector<JointVector> w{from, to};
    const auto path = CubicSplinePath::through(w, metric);
    ASSERT_TRUE(path.ok());
    ASSERT_EQ(path.value().segmentCount(), 1);
    const JointVector lo = from.cwiseMin(to), hi = from.cwiseMax(to);
    const auto bounds = path.value().segmentBounds(0);
    for (int j = 0; j < 2; ++j) {
      EXPECT_GE(bounds.q_min[j], lo[j]) << from.transpose() << " -> " << to.transpose() << " joint " << j;
      EXPECT_LE(bounds.q_max[j], hi[j]) << from.transpose() << " -> " << to.transpose() << " joint " << j;
    }
    EXPECT_EQ(path.value().at(0.0).q, from);
    EXPECT_EQ(path.value().at(path.value().length()).q, to);
    // Dense samples: inside the ends' box but for rounding far below any limit check's tolerance.
    for (int i = 0; i <= 10000; ++i) {
      const JointVector q = path.value().at(path.value().length() * i / 10000.0).q;
      for (int j = 0; j < 2; ++j) {
        EXPECT_GE(q[j], lo[j] - 1e-15) << i;
        EXPECT_LE(q[j], hi[j] + 1e-15) << i;
      }
    }
  }
}

TEST(CubicSplinePath, ReproducesEveryKnotAndTheGoalExactly) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> goal_t(-0.5, 0.5), goal_th(0.0, 0.9);
  for (int trial = 0; trial < 200; ++trial) {
    auto w = randomWaypoints(rng, 2 + trial % 8);
    const double gt = goal_t(rng);
    w.back() = JointVector{{w.back()[0] + gt, goal_th(rng)}};
    const auto path =
        CubicSplinePath::through(w, kMetric, trial % 3 == 0 ? JointVector{{0.3, -1.0}} : JointVector::Zero(2));
    ASSERT_TRUE(path.ok());
    const auto& knots = path.value().knots();
    for (size_t k = 0; k < knots.size(); ++k) EXPECT_EQ(path.value().at(knots[k]).q, w[k]) << trial << " knot " << k;
    // The segment bounds hold the knots exactly too.
    for (int k = 0; k < path.value().segmentCount(); ++k) {
      const auto bounds = path.value().segmentBounds(k);
      for (size_t e : {static_cast<size_t>(k), static_cast<size_t>(k) + 1}) {
        for (int j = 0; j < 2; ++j) {
          EXPECT_LE(bounds.q_min[j], w[e][j]);
          EXPECT_GE(bounds.q_max[j], w[e][j]);
        }
      }
    }
  }
}

TEST(CubicSplinePath, EvaluationDoesNotAllocate) {
  std::mt19937 rng(6);
  const auto w = randomWaypoints(rng, 30);
  const auto path = CubicSplinePath::through(w, kMetric);
  ASSERT_TRUE(path.ok());
  const GeometricPath& geometric = path.value();
  const long before = cyber::test::allocationCount();
  double sum = 0.0;
  for (int i = 0; i <= 10000; ++i) sum += geometric.at(geometric.length() * i / 10000.0).q.sum();
  const long after = cyber::test::allocationCount();
  EXPECT_EQ(after, before);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace cyber::planner

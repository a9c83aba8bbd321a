// Eq. 8: the gradient of J against central differences, the banded Hessian of its quadratic part,
// the optimiser's invariants, and polyline resampling.

#include "path/path_optimizer.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <limits>

#include "reference_model.hpp"

namespace cyber::planner {
namespace {

const RobotModel& model() { return test::referenceModel(); }

double weightedNorm(const JointVector& v) {
  const JointVector& m = model().planner.metric;
  return std::sqrt(m[0] * v[0] * v[0] + m[1] * v[1] * v[1]);
}

// A wavy path through the reef area: many waypoints within the obstacle term's reach.
std::vector<JointVector> wavyPath(int count) {
  std::vector<JointVector> w;
  for (int k = 0; k < count; ++k) {
    const double f = static_cast<double>(k) / (count - 1);
    w.push_back(JointVector{{0.5 + 1.2 * f + 0.05 * std::sin(9.0 * f), 4.9 + 0.9 * f + 0.2 * std::cos(7.0 * f)}});
  }
  return w;
}

TEST(SmoothingObjective, GradientMatchesCentralDifferences) {
  const CollisionWorld world(model(), model().scenes.front(), test::referencePieces("coral"));
  const std::vector<JointVector> prior = wavyPath(30);
  std::mt19937 rng(41);
  std::normal_distribution<double> noise(0.0, 0.01);
  int checked = 0, near_obstacles = 0;
  for (int fixed_head : {1, 2}) {
    const SmoothingObjective objective(world, prior, fixed_head, model(), model().planner.smoothing);
    ASSERT_EQ(objective.freeCount(), 30 - 1 - fixed_head);
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::VectorXd x = objective.priorVariables();
      for (Eigen::Index i = 0; i < x.size(); ++i) x[i] += noise(rng);
      Eigen::VectorXd gradient(x.size()), scratch(x.size());
      objective.evaluate(x, gradient);
      for (Eigen::Index i = 0; i < x.size(); ++i) {
        const double h = 1e-7;
        Eigen::VectorXd plus = x, minus = x;
        plus[i] += h;
        minus[i] -= h;
        const double f0 = objective.evaluate(x, scratch);
        const double fp = objective.evaluate(plus, scratch);
        const double fm = objective.evaluate(minus, scratch);
        // Skip the measure-zero kinks of d (a closest feature switching inside the step).
        if (std::abs((fp - f0) - (f0 - fm)) > 1e-9) continue;
        ++checked;
        const double central = (fp - fm) / (2 * h);
        // The difference quotient carries rounding of about eps |J| / h (J grows with the weights).
        const double rounding = 8.0 * std::numeric_limits<double>::epsilon() * std::abs(f0) / h;
        EXPECT_NEAR(gradient[i], central, 1e-5 * std::max(1.0, std::abs(central)) + rounding) << "variable " << i;
      }
      const std::vector<JointVector> w = objective.waypoints(x);
      for (int k = fixed_head; k + 1 < 30; ++k) {
        if (world.distance(w[static_cast<size_t>(k)]).value <
            kObstacleCutoffDecays * model().planner.smoothing.obstacle_decay_m) {
          ++near_obstacles;
        }
      }
    }
  }
  EXPECT_GT(checked, 1800);
  EXPECT_GT(near_obstacles, 200) << "the obstacle term is exercised";
}

TEST(SmoothingObjective, BandedHessianIsThatOfTheQuadraticPart) {
  // Without obstacles J is quadratic inside the limits, so gradient differences along any
  // direction v equal H v exactly.
  const CollisionWorld empty(model(), Scene{"empty", {}, {}, {}}, HeldPieces{});
  const std::vector<JointVector> prior = wavyPath(12);
  const SmoothingObjective objective(empty, prior, 2, model(), model().planner.smoothing);
  const int m = objective.freeCount();
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  Eigen::VectorXd x = objective.priorVariables(), v(2 * m), g0(2 * m), g1(2 * m);
  for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = 1e-3 * noise(rng);
  objective.evaluate(x, g0);
  objective.evaluate(x + v, g1);
  for (int joint = 0; joint < 2; ++joint) {
    BandedCholesky h;
    objective.quadraticHessian(joint, h);
    ASSERT_EQ(h.size(), m);
    ASSERT_EQ(h.bandwidth(), 2);
    for (int k = 0; k < m; ++k) {
      double hv = 0.0;
      for (int i = std::max(0, k - 2); i <= std::min(m - 1, k + 2); ++i) hv += h.entry(k, i) * v[joint * m + i];
      EXPECT_NEAR(hv, g1[joint * m + k] - g0[joint * m + k], 1e-10) << "joint " << joint << " k " << k;
    }
  }
}

TEST(OptimizePath, LowersTheCostAndKeepsTheFixedWaypoints) {
  const CollisionWorld world(model(), model().scenes.front(), HeldPieces{});
  const std::vector<JointVector> prior = wavyPath(25);
  for (int fixed_head : {1, 2}) {
    const SmoothingResult result = optimizePath(world, prior, fixed_head, model(), model().planner.smoothing);
    ASSERT_EQ(result.waypoints.size(), prior.size());
    for (int k = 0; k < fixed_head; ++k)
      EXPECT_EQ(result.waypoints[static_cast<size_t>(k)], prior[static_cast<size_t>(k)]);
    EXPECT_EQ(result.waypoints.back(), prior.back());
    const SmoothingObjective objective(world, prior, fixed_head, model(), model().planner.smoothing);
    Eigen::VectorXd g(2 * objective.freeCount());
    Eigen::VectorXd x_prior = objective.priorVariables(), x_result(x_prior.size());
    for (int k = 0; k < objective.freeCount(); ++k) {
      x_result[k] = result.waypoints[static_cast<size_t>(fixed_head + k)][0];
      x_result[objective.freeCount() + k] = result.waypoints[static_cast<size_t>(fixed_head + k)][1];
    }
    EXPECT_LT(objective.evaluate(x_result, g), 0.9 * objective.evaluate(x_prior, g));
    EXPECT_GT(result.lbfgs.iterations, 0);
    for (const JointVector& q : result.waypoints) EXPECT_TRUE(model().withinLimits(q));
  }
}

TEST(OptimizePath, KeepsWaypointsInsideTheLimits) {
  // A prior running along the top of the elevator: the result stays inside by the margin.
  const CollisionWorld world(model(), model().scenes.front(), HeldPieces{});
  std::vector<JointVector> prior;
  for (int k = 0; k <= 20; ++k) prior.push_back(JointVector{{2.0, 1.0 + 0.05 * k}});
  const SmoothingResult result = optimizePath(world, prior, 1, model(), model().planner.smoothing);
  for (size_t k = 1; k + 1 < result.waypoints.size(); ++k) {
    EXPECT_LE(result.waypoints[k][0], model().range(0).max - model().planner.grid.joint_limit_margin + 1e-12);
  }
}

TEST(OptimizePath, NothingToOptimiseReturnsThePrior) {
  const CollisionWorld world(model(), model().scenes.front(), HeldPieces{});
  const std::vector<JointVector> two{JointVector{{0.2, 1.57}}, JointVector{{0.5, 2.0}}};
  EXPECT_EQ(optimizePath(world, two, 1, model(), model().planner.smoothing).waypoints, two);
}

TEST(ResamplePolyline, EqualWeightedSpacingOnThePolylineWithExactEnds) {
  const std::vector<JointVector> polyline{JointVector{{0.0, 0.0}}, JointVector{{0.3, 0.0}}, JointVector{{0.3, 2.0}},
                                          JointVector{{0.3, 2.0}}, JointVector{{1.0, 2.5}}};
  const auto out = resamplePolyline(polyline, model().planner.metric, 0.05);
  ASSERT_GE(out.size(), 3U);
  EXPECT_EQ(out.front(), polyline.front());
  EXPECT_EQ(out.back(), polyline.back());
  double total = 0.0;
  for (size_t k = 1; k < polyline.size(); ++k) total += weightedNorm(polyline[k] - polyline[k - 1]);
  const double spacing = total / static_cast<double>(out.size() - 1);
  EXPECT_LE(spacing, 0.05);
  EXPECT_GT(spacing, 0.05 * (out.size() - 2) / (out.size() - 1));
  for (const JointVector& q : out) {
    // On one of the polyline's segments.
    double best = 1e9;
    for (size_t k = 1; k < polyline.size(); ++k) {
      const JointVector e = polyline[k] - polyline[k - 1];
      const double u = e.squaredNorm() > 0 ? std::clamp((q - polyline[k - 1]).dot(e) / e.squaredNorm(), 0.0, 1.0) : 0.0;
      best = std::min(best, (q - (polyline[k - 1] + u * e)).norm());
    }
    EXPECT_LT(best, 1e-12);
  }
  // Arc length between consecutive samples along the polyline is the spacing: their chords can
  // only be shorter (corners), never longer.
  for (size_t k = 1; k < out.size(); ++k) EXPECT_LE(weightedNorm(out[k] - out[k - 1]), spacing + 1e-12);
}

}  // namespace
}  // namespace cyber::planner

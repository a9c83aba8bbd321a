// The augmented Lagrangian of the time-optimal parameterisation (topp_augmented_lagrangian.hpp):
// the variable layout against a count of its slots, the warm start against its closed form, L_rho
// against the cost at a feasible point and its gradient against finite differences, the solver
// from a cold start against the warm-started one, and a stiff solve of a random robot.

#include "timing/topp_augmented_lagrangian.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "cyber/planner/motion_planner.hpp"
#include "random_robot.hpp"
#include "timing/topp_reachability.hpp"
#include "topp_fixtures.hpp"

namespace cyber::planner {
namespace {

TEST(ToppVariableLayout, NumbersEveryVariableOnceAndKeepsEachConstraintInTheBand) {
  for (const int grid_points : {2, 3, 7, 50}) {
    const topp::VariableLayout v{grid_points};
    std::vector<int> owners(static_cast<size_t>(v.size()), 0);
    auto own = [&](int i) {
      ASSERT_GE(i, 0);
      ASSERT_LT(i, v.size());
      ++owners[static_cast<size_t>(i)];
    };
    for (int k = 0; k < grid_points; ++k) {
      own(v.b(k));
      own(v.c(k));
    }
    for (int k = 0; k < v.intervals(); ++k) {
      own(v.a(k));
      own(v.d(k));
    }
    for (size_t i = 0; i < owners.size(); ++i) EXPECT_EQ(owners[i], 1) << "variable " << i << ", K " << grid_points;
    // Every term of L_rho couples the variables of one interval: a limit row, its time cone, its
    // b-a relation. Their spread is what the Hessian's band must hold.
    for (int k = 0; k < v.intervals(); ++k) {
      const topp::VariableLayout::Row row = v.row(k);
      EXPECT_EQ(row.a, v.a(k));
      EXPECT_EQ(row.b0, v.b(k));
      EXPECT_EQ(row.b1, v.b(k + 1));
      EXPECT_EQ(row.c0, v.c(k));
      EXPECT_EQ(row.c1, v.c(k + 1));
      const int lowest = std::min({row.a, row.b0, row.c0, v.d(k)});
      const int highest = std::max({row.b1, row.c1, v.d(k)});
      EXPECT_LE(highest - lowest, topp::VariableLayout::kBandwidth) << "interval " << k << ", K " << grid_points;
    }
    const std::array<int, 4> boundary = v.boundary();
    EXPECT_EQ(boundary[0], v.b(0));
    EXPECT_EQ(boundary[1], v.b(grid_points - 1));
    EXPECT_EQ(boundary[2], v.c(0));
    EXPECT_EQ(boundary[3], v.c(grid_points - 1));
  }
}

// x from a profile b: c = sqrt(b), a from the b-a relation of each interval, d = 1 / (c_k + c_k+1).
TEST(ToppAugmentedLagrangian, InitialGuessIsTheProfilesClosedForm) {
  const topp::Problem p = testing::wiggleProblem(30);
  std::vector<double> b(static_cast<size_t>(p.gridPoints()));
  for (size_t k = 0; k < b.size(); ++k) b[k] = 0.6 + 0.5 * std::sin(0.3 * static_cast<double>(k));
  b.front() = 0.0;
  Eigen::VectorXd x;
  topp::initialGuess(p, b, x);
  const topp::VariableLayout v{p.gridPoints()};
  ASSERT_EQ(x.size(), v.size());
  for (int k = 0; k < p.gridPoints(); ++k) {
    EXPECT_EQ(x[v.b(k)], b[static_cast<size_t>(k)]);
    EXPECT_DOUBLE_EQ(x[v.c(k)], std::sqrt(b[static_cast<size_t>(k)]));
  }
  for (int k = 0; k < p.intervals(); ++k) {
    EXPECT_NEAR(x[v.b(k + 1)] - x[v.b(k)] - 2.0 * p.ds(k) * x[v.a(k)], 0.0, 1e-12) << "interval " << k;
    EXPECT_NEAR(x[v.d(k)] * (x[v.c(k)] + x[v.c(k + 1)]), 1.0, 1e-12) << "interval " << k;
  }
}

// At a point that meets every constraint, with zero multipliers, every penalty of L_rho is zero
// and L_rho is the cost, sum 2 ds d (times cost_scale), whatever rho.
TEST(ToppAugmentedLagrangian, AtAFeasiblePointWithoutMultipliersTheValueIsTheCost) {
  testing::WarmStart w = testing::wiggleWarmStart(80);
  topp::Problem& p = w.problem;
  p.cost_scale = 0.7;
  // Slowed to 90 %, off every limit row (the profile itself sits on them).
  std::vector<double> b = w.profile;
  for (double& value : b) value *= 0.81;
  Eigen::VectorXd x;
  topp::initialGuess(p, b, x);
  const topp::VariableLayout v{p.gridPoints()};
  double cost = 0.0;
  for (int k = 0; k < p.intervals(); ++k) cost += p.cost_scale * 2.0 * p.ds(k) * x[v.d(k)];
  topp::Multipliers zero;
  zero.reset(p);
  Eigen::VectorXd grad(x.size());
  for (const double rho : {1.0, 1e3}) {
    EXPECT_NEAR(topp::augmentedLagrangian(p, zero, rho, x, grad), cost, 1e-9 * rho * cost) << "rho " << rho;
  }
  // Off the constraints the penalties add: faster than the profile breaks a limit row.
  for (double& value : b) value *= 1.5;
  topp::initialGuess(p, b, x);
  cost = 0.0;
  for (int k = 0; k < p.intervals(); ++k) cost += p.cost_scale * 2.0 * p.ds(k) * x[v.d(k)];
  EXPECT_GT(topp::augmentedLagrangian(p, zero, 1e3, x, grad), cost + 1.0);
}

TEST(ToppAugmentedLagrangian, MultipliersHaveOneSlotPerConstraint) {
  const topp::Problem p = testing::wiggleProblem(25);
  topp::Multipliers m;
  m.reset(p);
  const int kk = p.gridPoints();
  EXPECT_EQ(m.time_cone.size(), 3 * (kk - 1));
  EXPECT_EQ(m.speed_cone.size(), 3 * kk);
  EXPECT_EQ(m.speed_square.size(), kk);
  EXPECT_EQ(m.equality.size(), (kk - 1) + 4);  // one per interval, then the four boundary values
  EXPECT_EQ(m.row_upper.size(), static_cast<Eigen::Index>(p.rows.size()));
  EXPECT_EQ(m.row_lower.size(), static_cast<Eigen::Index>(p.rows.size()));
  EXPECT_EQ(m.b_nonnegative.size(), kk);
  EXPECT_EQ(&m.boundary(0), m.equality.data() + (kk - 1));
  EXPECT_EQ(m.timeCone(kk - 2), m.time_cone.data() + 3 * (kk - 2));
  EXPECT_EQ(m.speedCone(kk - 1), m.speed_cone.data() + 3 * (kk - 1));
}

TEST(ToppAugmentedLagrangian, GradientMatchesFiniteDifferences) {
  testing::WarmStart w = testing::wiggleWarmStart(40);
  const topp::Problem& p = w.problem;
  Eigen::VectorXd& x = w.x;
  topp::Multipliers& m = w.multipliers;
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  // Perturb away from kinks (active-set boundaries) so the central difference is meaningful.
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] += 1e-3 * g(rng);
  for (Eigen::Index i = 0; i < m.row_upper.size(); ++i) m.row_upper[i] += 1e-3 * std::abs(g(rng));
  const double rho = 50.0;
  Eigen::VectorXd grad(x.size()), scratch(x.size());
  topp::augmentedLagrangian(p, m, rho, x, grad);
  const double h = 1e-6;
  int checked = 0;
  for (Eigen::Index i = 0; i < x.size(); i += 3) {
    Eigen::VectorXd xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    const double fd =
        (topp::augmentedLagrangian(p, m, rho, xp, scratch) - topp::augmentedLagrangian(p, m, rho, xm, scratch)) /
        (2 * h);
    EXPECT_NEAR(grad[i], fd, 1e-5 * (1.0 + std::abs(fd))) << "variable " << i;
    ++checked;
  }
  EXPECT_GT(checked, 40);
}

TEST(ToppAugmentedLagrangian, ColdStartReachesTheSameOptimumAsTheWarmStart) {
  const testing::WarmStart start = testing::wiggleWarmStart(60);
  const topp::Problem& p = start.problem;
  topp::AlSettings settings;
  settings.max_outer_iterations = 200;
  settings.max_inner_iterations = 2000;

  topp::AlState warm;
  warm.x = start.x;
  warm.multipliers = start.multipliers;
  topp::AlWorkspace workspace;
  const topp::AlReport w = topp::solveAugmentedLagrangian(p, settings, warm, workspace);
  ASSERT_TRUE(w.converged);

  // Cold: zero multipliers, the reachability profile slowed down to 80 %.
  topp::AlState cold;
  std::vector<double> slow = start.profile;
  for (double& v : slow) v *= 0.64;
  topp::initialGuess(p, slow, cold.x);
  cold.multipliers.reset(p);
  const topp::AlReport c = topp::solveAugmentedLagrangian(p, settings, cold, workspace);
  ASSERT_TRUE(c.converged) << c.primal_residual << " " << c.dual_residual;
  EXPECT_GT(c.inner_iterations, w.inner_iterations);  // the warm start saves work
  EXPECT_NEAR(c.cost, w.cost, 1e-4 * w.cost);
  EXPECT_LE(c.primal_residual, settings.primal_tolerance);
  EXPECT_LE(c.dual_residual, settings.dual_tolerance);
}

// A stiff solve: random robot 4's move 8, from rest. There the preconditioned test of an inner
// minimisation (|g| <= |L| |g_z|) is far stricter than the gradient's own, and when only it
// ended one, every outer step ran to its 500 iterations: 19 368 in 44 steps. Ended as soon as the
// gradient meets the step's target, the plan takes 2 115.
TEST(ToppAugmentedLagrangian, AnInnerMinimisationEndsOnceTheGradientMeetsItsTarget) {
  const test::RandomRobot robot = test::randomRobot(4);
  const MotionPlanner planner = MotionPlanner::create(robot.config.robot).value();
  // The move as RandomMoveDraw draws it natively (written out: the draw itself depends on earlier
  // plans, which differ in their last bits between targets).
  PlanRequest request;
  request.start = JointVector{{0.49469241766096134, 0.029674314819465305}};
  request.goal = JointVector{{0.717930668274171, 0.19913280437377637}};
  request.pieces = HeldPieces{}.with(0);
  const Result<Plan> plan = planner.plan(request);
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  EXPECT_LT(plan.value().solver.inner_iterations, 5000);
}

}  // namespace
}  // namespace cyber::planner

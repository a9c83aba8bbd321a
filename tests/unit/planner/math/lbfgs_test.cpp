// L-BFGS with the weak-Wolfe line search: smooth, convex, nonsmooth and non-finite cases.

#include "math/lbfgs.hpp"

#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace cyber::planner {
namespace {

double rosenbrock(const Eigen::VectorXd& x, Eigen::VectorXd& g) {
  double f = 0.0;
  g.setZero();
  for (Eigen::Index i = 0; i + 1 < x.size(); ++i) {
    const double a = x[i + 1] - x[i] * x[i];
    const double b = 1.0 - x[i];
    f += 100.0 * a * a + b * b;
    g[i] += -400.0 * a * x[i] - 2.0 * b;
    g[i + 1] += 200.0 * a;
  }
  return f;
}

TEST(Lbfgs, RosenbrockTwoDimensionsReachesTheMinimum) {
  Eigen::VectorXd x(2);
  x << -1.2, 1.0;
  LbfgsSettings settings;
  settings.gradient_tolerance = 1e-8;
  const LbfgsResult r = minimizeLbfgs(rosenbrock, x, settings);
  EXPECT_EQ(r.status, LbfgsStatus::kConverged);
  EXPECT_NEAR(x[0], 1.0, 1e-6);
  EXPECT_NEAR(x[1], 1.0, 1e-6);
  EXPECT_LT(r.cost, 1e-12);
  EXPECT_LE(r.gradient_norm, 1e-8);
  EXPECT_GT(r.iterations, 5);
  EXPECT_GE(r.evaluations, r.iterations + 1);
}

TEST(Lbfgs, RosenbrockManyDimensions) {
  Eigen::VectorXd x = Eigen::VectorXd::Constant(30, -0.5);
  LbfgsSettings settings;
  settings.max_iterations = 2000;
  const LbfgsResult r = minimizeLbfgs(rosenbrock, x, settings);
  EXPECT_EQ(r.status, LbfgsStatus::kConverged);
  EXPECT_LT((x - Eigen::VectorXd::Ones(30)).norm(), 1e-4);
}

TEST(Lbfgs, SeededRandomSpdQuadraticsMatchTheClosedForm) {
  std::mt19937 rng(1234);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 2 + trial * 3;
    Eigen::MatrixXd m(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) m(i, j) = normal(rng);
    const Eigen::MatrixXd a = m * m.transpose() + 0.1 * Eigen::MatrixXd::Identity(n, n);
    Eigen::VectorXd b(n);
    for (int i = 0; i < n; ++i) b[i] = normal(rng);
    const Eigen::VectorXd exact = a.ldlt().solve(b);
    auto f = [&](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
      g = a * x - b;
      return 0.5 * x.dot(a * x) - b.dot(x);
    };
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    LbfgsSettings settings;
    settings.gradient_tolerance = 1e-9;  // below the Armijo roundoff floor: needs the approximate test
    settings.max_iterations = 5000;
    const LbfgsResult r = minimizeLbfgs(f, x, settings);
    ASSERT_EQ(r.status, LbfgsStatus::kConverged)
        << "n=" << n << " it=" << r.iterations << " g=" << r.gradient_norm << " f=" << r.cost;
    // |x - x*| <= |g| / lambda_min(A) and lambda_min >= 0.1.
    EXPECT_LE((x - exact).norm(), 1e-9 / 0.1 * 1.01) << "n=" << n;
    EXPECT_NEAR(r.cost, -0.5 * b.dot(exact), 1e-12 * std::max(1.0, std::abs(b.dot(exact))));
  }
}

TEST(Lbfgs, ReusedWorkspaceGivesTheSameResult) {
  LbfgsWorkspace workspace;
  for (int n : {4, 7, 4}) {
    Eigen::VectorXd x1 = Eigen::VectorXd::Constant(n, -0.3);
    Eigen::VectorXd x2 = x1;
    LbfgsSettings settings;
    settings.max_iterations = 1000;
    const LbfgsResult a = minimizeLbfgs(rosenbrock, x1, settings);
    const LbfgsResult b = minimizeLbfgs(rosenbrock, x2, settings, workspace);
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_EQ(a.evaluations, b.evaluations);
    EXPECT_EQ(x1, x2);
  }
}

TEST(Lbfgs, NonsmoothAbsoluteValueCostGetsCloseToTheKink) {
  // f = |x0 - 1| + 2|x1 + 0.5| + 0.1 |x|^2 has its minimum at a kink; L-BFGS cannot certify it
  // by the gradient, but the weak-Wolfe line search still makes progress down to the kink.
  auto f = [](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
    const double s0 = x[0] > 1.0 ? 1.0 : -1.0;
    const double s1 = x[1] > -0.5 ? 1.0 : -1.0;
    g[0] = s0 + 0.2 * x[0];
    g[1] = 2.0 * s1 + 0.2 * x[1];
    return std::abs(x[0] - 1.0) + 2.0 * std::abs(x[1] + 0.5) + 0.1 * x.squaredNorm();
  };
  Eigen::VectorXd x(2);
  x << 3.7, 2.2;
  LbfgsSettings settings;
  settings.max_iterations = 500;
  settings.max_line_search_steps = 60;
  const LbfgsResult r = minimizeLbfgs(f, x, settings);
  EXPECT_NE(r.status, LbfgsStatus::kNonFinite);
  EXPECT_NE(r.status, LbfgsStatus::kConverged);  // the gradient never vanishes at a kink
  EXPECT_NEAR(x[0], 1.0, 1e-5);
  EXPECT_NEAR(x[1], -0.5, 1e-5);
  EXPECT_NEAR(r.cost, 0.1 * 1.25, 1e-5);
}

TEST(Lbfgs, NonfiniteStartIsReportedWithoutIterating) {
  Eigen::VectorXd x(2);
  x << std::numeric_limits<double>::quiet_NaN(), 0.0;
  const LbfgsResult r = minimizeLbfgs(rosenbrock, x, LbfgsSettings{});
  EXPECT_EQ(r.status, LbfgsStatus::kNonFinite);
  EXPECT_EQ(r.iterations, 0);

  Eigen::VectorXd y(1);
  y << 2.0;
  auto bad = [](const Eigen::VectorXd&, Eigen::VectorXd& g) {
    g[0] = 1.0;
    return std::numeric_limits<double>::infinity();
  };
  const LbfgsResult r2 = minimizeLbfgs(bad, y, LbfgsSettings{});
  EXPECT_EQ(r2.status, LbfgsStatus::kNonFinite);
  EXPECT_EQ(y[0], 2.0);
}

TEST(Lbfgs, NonfiniteRegionIsTreatedAsTooLongAStep) {
  // -log(x) + x: minimum at 1, +inf (NaN for the log) for x <= 0.
  auto f = [](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
    g[0] = -1.0 / x[0] + 1.0;
    return -std::log(x[0]) + x[0];
  };
  Eigen::VectorXd x(1);
  x << 0.05;  // the gradient points far into the non-finite half line
  const LbfgsResult r = minimizeLbfgs(f, x, LbfgsSettings{});
  EXPECT_EQ(r.status, LbfgsStatus::kConverged);
  EXPECT_NEAR(x[0], 1.0, 1e-5);
}

TEST(Lbfgs, IterationCapIsReported) {
  Eigen::VectorXd x(2);
  x << -1.2, 1.0;
  LbfgsSettings settings;
  settings.max_iterations = 3;
  const LbfgsResult r = minimizeLbfgs(rosenbrock, x, settings);
  EXPECT_EQ(r.status, LbfgsStatus::kMaxIterations);
  EXPECT_EQ(r.iterations, 3);
  EXPECT_GT(r.gradient_norm, settings.gradient_tolerance);
}

TEST(Lbfgs, AlreadyOptimalAndEmptyProblemsConvergeImmediately) {
  Eigen::VectorXd x = Eigen::VectorXd::Ones(3);
  const LbfgsResult r = minimizeLbfgs(rosenbrock, x, LbfgsSettings{});
  EXPECT_EQ(r.status, LbfgsStatus::kConverged);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(r.evaluations, 1);

  Eigen::VectorXd empty(0);
  auto zero = [](const Eigen::VectorXd&, Eigen::VectorXd&) { return 0.0; };
  EXPECT_EQ(minimizeLbfgs(zero, empty, LbfgsSettings{}).status, LbfgsStatus::kConverged);
}

TEST(Lbfgs, LineSearchFailureKeepsTheLastIterate) {
  // A wrong gradient (sign flipped) makes every direction an ascent direction for the cost.
  auto lying = [](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
    g = -x;
    return 0.5 * x.squaredNorm();
  };
  Eigen::VectorXd x(2);
  x << 1.0, -2.0;
  LbfgsSettings settings;
  settings.max_line_search_steps = 10;
  const LbfgsResult r = minimizeLbfgs(lying, x, settings);
  EXPECT_EQ(r.status, LbfgsStatus::kLineSearchFailed);
  EXPECT_EQ(x[0], 1.0);
  EXPECT_EQ(x[1], -2.0);
  EXPECT_EQ(r.evaluations, 11);
}

TEST(Lbfgs, RelativeCostToleranceStopsEarly) {
  Eigen::VectorXd x(2);
  x << -1.2, 1.0;
  LbfgsSettings settings;
  settings.gradient_tolerance = 0.0;
  settings.relative_cost_tolerance = 1e-3;
  const LbfgsResult r = minimizeLbfgs(rosenbrock, x, settings);
  EXPECT_EQ(r.status, LbfgsStatus::kConverged);
  EXPECT_LT(r.iterations, settings.max_iterations);
}

}  // namespace
}  // namespace cyber::planner

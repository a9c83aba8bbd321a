// The banded Hessian of L_rho (topp_al_hessian.cpp, algorithm.md eqs. 19-23) against central
// differences of L_rho's gradient, entry by entry over the whole matrix: equal wherever the
// generalised Gauss-Newton form is the exact Hessian, larger by exactly the curvature it leaves
// out where c^2 - b + nu / rho < 0, never coupling variables outside its band, and a factor
// without replaced pivots (it preconditions the inner L-BFGS).

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "math/banded_cholesky.hpp"
#include "timing/topp_augmented_lagrangian.hpp"
#include "topp_fixtures.hpp"

namespace cyber::planner {
namespace {

// The warm start of a 40-point S-curve, moved off every kink of L_rho (active-set boundaries, the
// cones' apex) by a seeded perturbation, with multipliers that keep some rows active.
struct Point {
  topp::Problem problem;
  Eigen::VectorXd x;
  topp::Multipliers multipliers;
};

Point perturbedWarmStart(unsigned seed) {
  testing::WarmStart w = testing::wiggleWarmStart(40);
  Point p{std::move(w.problem), std::move(w.x), std::move(w.multipliers)};
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  for (Eigen::Index i = 0; i < p.x.size(); ++i) p.x[i] += 1e-3 * g(rng);
  for (Eigen::Index i = 0; i < p.multipliers.row_upper.size(); ++i)
    p.multipliers.row_upper[i] += 1e-3 * std::abs(g(rng));
  for (Eigen::Index i = 0; i < p.multipliers.time_cone.size(); ++i) p.multipliers.time_cone[i] += 1e-3 * g(rng);
  for (Eigen::Index i = 0; i < p.multipliers.speed_square.size(); ++i) p.multipliers.speed_square[i] += 1e-2 * g(rng);
  return p;
}

// The Hessian of L_rho by differences of its gradient, column by column: forward, backward and
// central. L_rho is piecewise smooth; where a column's step crosses a kink (a row becoming active,
// a cone argument crossing its boundary) only the one-sided difference that stays on x's side of
// it is the Hessian at x.
struct Differences {
  Eigen::MatrixXd forward, backward, central;
};

Differences finiteDifferenceHessian(const Point& p, double rho, double h) {
  const Eigen::Index n = p.x.size();
  Differences d{Eigen::MatrixXd(n, n), Eigen::MatrixXd(n, n), Eigen::MatrixXd(n, n)};
  Eigen::VectorXd at(n), plus(n), minus(n);
  topp::augmentedLagrangian(p.problem, p.multipliers, rho, p.x, at);
  for (Eigen::Index j = 0; j < n; ++j) {
    Eigen::VectorXd xp = p.x, xm = p.x;
    xp[j] += h;
    xm[j] -= h;
    topp::augmentedLagrangian(p.problem, p.multipliers, rho, xp, plus);
    topp::augmentedLagrangian(p.problem, p.multipliers, rho, xm, minus);
    d.forward.col(j) = (plus - at) / h;
    d.backward.col(j) = (at - minus) / h;
    d.central.col(j) = (plus - minus) / (2.0 * h);
  }
  return d;
}

TEST(ToppAlHessian, IsTheFiniteDifferenceHessianUpToTheCurvatureItLeavesOut) {
  for (const unsigned seed : {3u, 4u, 5u}) {
    const Point p = perturbedWarmStart(seed);
    const double rho = 50.0;
    BandedCholesky assembled;
    topp::assembleHessian(p.problem, p.multipliers, rho, p.x, assembled);
    Differences fd = finiteDifferenceHessian(p, rho, 1e-6);
    const topp::VariableLayout v{p.problem.gridPoints()};
    ASSERT_EQ(assembled.size(), v.size());
    // Where (c^2 - b + nu / rho) < 0 the exact Hessian of its square has 2 rho times it on the
    // c-c entry: negative curvature a preconditioner must not have, so it is left out.
    int left_out = 0, kept = 0;
    for (int k = 1; k + 1 < p.problem.gridPoints(); ++k) {
      const double b = p.x[v.b(k)], c = p.x[v.c(k)];
      const double shifted = c * c - b + p.multipliers.speed_square[k] / rho;
      if (shifted < 0.0) {
        for (Eigen::MatrixXd* m : {&fd.forward, &fd.backward, &fd.central}) (*m)(v.c(k), v.c(k)) -= 2.0 * rho * shifted;
        ++left_out;
      } else {
        ++kept;
      }
    }
    EXPECT_GT(left_out, 0) << "seed " << seed;
    EXPECT_GT(kept, 0) << "seed " << seed;
    const double tolerance = 1e-6 * fd.central.cwiseAbs().maxCoeff();
    // The floor adds a millionth of each variable's curvature with every term active.
    auto matches = [&](double value, double expected, bool diagonal) {
      return diagonal ? value >= expected - tolerance && value <= expected * (1.0 + 1e-3) + tolerance
                      : std::abs(value - expected) <= tolerance;
    };
    int one_sided = 0, entries = 0;
    for (Eigen::Index i = 0; i < fd.central.rows(); ++i) {
      for (Eigen::Index j = 0; j <= i; ++j) {
        const double a = assembled.entry(i, j);
        const bool diagonal = i == j;
        ++entries;
        if (matches(a, fd.central(i, j), diagonal) || matches(a, fd.central(j, i), diagonal)) continue;
        ++one_sided;
        const bool either_side = matches(a, fd.forward(i, j), diagonal) || matches(a, fd.backward(i, j), diagonal) ||
                                 matches(a, fd.forward(j, i), diagonal) || matches(a, fd.backward(j, i), diagonal);
        EXPECT_TRUE(either_side) << "seed " << seed << ", (" << i << ", " << j << "): " << a << " against "
                                 << fd.central(i, j) << (i - j > v.kBandwidth ? ", outside the band" : "");
      }
    }
    // A kink within 1e-6 of x is rare: nearly every entry is the central difference's.
    EXPECT_LT(one_sided, entries / 1000) << "seed " << seed;
  }
}

// Whatever the multipliers and rho, the assembled matrix is positive definite: its factor
// replaces no pivot.
TEST(ToppAlHessian, FactorsWithoutReplacingAPivot) {
  for (const unsigned seed : {6u, 7u}) {
    Point p = perturbedWarmStart(seed);
    for (const double rho : {1.0, 1e3, 1e6}) {
      BandedCholesky h;
      topp::assembleHessian(p.problem, p.multipliers, rho, p.x, h);
      EXPECT_EQ(h.factor(), 0) << "seed " << seed << ", rho " << rho;
    }
    p.multipliers.reset(p.problem);
    BandedCholesky h;
    topp::assembleHessian(p.problem, p.multipliers, 1e3, p.x, h);
    EXPECT_EQ(h.factor(), 0) << "seed " << seed << ", zero multipliers";
  }
}

}  // namespace
}  // namespace cyber::planner

// The banded Cholesky factor against a dense one (Eigen's LLT) on seeded random band matrices, its
// storage against the matrix it was given, and the floor it puts under pivots that are not
// positive (the factor must stay a usable preconditioner).

#include "math/banded_cholesky.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace cyber::planner {
namespace {

// A seeded random symmetric band matrix, diagonally dominant (so positive definite), both as the
// band and as its dense copy.
struct BandMatrix {
  Eigen::MatrixXd dense;
  BandedCholesky band;
};

BandMatrix randomSpd(int n, int w, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  BandMatrix m{Eigen::MatrixXd::Zero(n, n), {}};
  m.band.reset(n, w);
  for (int i = 0; i < n; ++i) {
    for (int j = std::max(0, i - w); j <= i; ++j) {
      const double v = i == j ? 2.0 * w + 1.0 + u(rng) : u(rng);
      m.dense(i, j) += v;
      if (i != j) m.dense(j, i) += v;
      m.band.add(i, j, v);
    }
  }
  return m;
}

// Whether the factor solves L L' x = 1 with finite values: what a preconditioner must do whatever
// pivots it had to replace.
bool solvesFinitely(const BandedCholesky& band) {
  Eigen::VectorXd x = Eigen::VectorXd::Ones(band.size());
  band.solveLower(x);
  band.solveUpper(x);
  return x.allFinite();
}

TEST(BandedCholesky, MatchesDenseFactorisationOnRandomBandMatrices) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 5 + trial * 7;
    const int w = 1 + trial % 6;
    BandMatrix m = randomSpd(n, w, rng);
    const Eigen::MatrixXd& a = m.dense;
    BandedCholesky& band = m.band;
    EXPECT_EQ(band.factor(), 0);
    const Eigen::MatrixXd l = a.llt().matrixL();
    Eigen::VectorXd rhs(n);
    for (int i = 0; i < n; ++i) rhs[i] = u(rng);
    Eigen::VectorXd lower = rhs;
    band.solveLower(lower);
    EXPECT_LT((lower - l.triangularView<Eigen::Lower>().solve(rhs)).norm(), 1e-10);
    Eigen::VectorXd upper = rhs;
    band.solveUpper(upper);
    EXPECT_LT((upper - l.transpose().triangularView<Eigen::Upper>().solve(rhs)).norm(), 1e-10);
    Eigen::VectorXd full = rhs;
    band.solveLower(full);
    band.solveUpper(full);
    EXPECT_LT((a * full - rhs).norm(), 1e-9);
  }
}

TEST(BandedCholesky, SingularMatricesStillGiveAUsableFactor) {
  BandedCholesky band;
  band.reset(3, 1);
  band.add(0, 0, 1.0);
  band.add(1, 0, 1.0);
  band.add(1, 1, 1.0);  // rows 0 and 1 equal: singular
  band.add(2, 2, 4.0);
  EXPECT_EQ(band.factor(), 1);
  EXPECT_TRUE(solvesFinitely(band));
}

// The factor holds L: after factor(), entry(i, j) for j <= i is Eigen's L(i, j) within the band,
// and Eigen's L is zero outside it (a band matrix's Cholesky factor has no fill-in).
TEST(BandedCholesky, FactorIsTheDenseLowerTriangleWithinTheBand) {
  std::mt19937 rng(19);
  for (const int w : {0, 1, 3, 8}) {
    BandMatrix m = randomSpd(12, w, rng);
    ASSERT_EQ(m.band.factor(), 0);
    const Eigen::MatrixXd l = m.dense.llt().matrixL();
    for (int i = 0; i < 12; ++i) {
      for (int j = 0; j <= i; ++j) {
        EXPECT_NEAR(m.band.entry(i, j), l(i, j), 1e-12) << "w " << w << " (" << i << ", " << j << ")";
      }
    }
  }
}

TEST(BandedCholesky, AddAccumulatesSymmetricallyAndResetClears) {
  BandedCholesky band;
  band.reset(4, 2);
  EXPECT_EQ(band.size(), 4);
  EXPECT_EQ(band.bandwidth(), 2);
  band.add(2, 0, 1.5);
  band.add(0, 2, 0.25);  // the same entry, from above the diagonal
  band.add(3, 3, 2.0);
  band.add(3, 3, 1.0);
  EXPECT_EQ(band.entry(2, 0), 1.75);
  EXPECT_EQ(band.entry(0, 2), 1.75);
  EXPECT_EQ(band.entry(3, 3), 3.0);
  EXPECT_EQ(band.entry(3, 0), 0.0);  // outside the band
  EXPECT_EQ(band.entry(0, 3), 0.0);
  band.reset(5, 1);
  EXPECT_EQ(band.size(), 5);
  EXPECT_EQ(band.bandwidth(), 1);
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) EXPECT_EQ(band.entry(i, j), 0.0) << i << ", " << j;
  }
}

// A pivot that is not positive (an indefinite matrix) is raised to min_pivot times its diagonal
// entry, once per such pivot, and the factor solves with finite values.
TEST(BandedCholesky, PivotsBelowTheFloorAreReplacedAndCounted) {
  BandedCholesky band;
  band.reset(4, 1);
  band.add(0, 0, 1.0);
  band.add(1, 0, 2.0);
  band.add(1, 1, 1.0);   // pivot 1 - 4 < 0
  band.add(2, 2, -3.0);  // negative on the diagonal
  band.add(3, 3, 5.0);
  EXPECT_EQ(band.factor(1e-6), 2);
  EXPECT_NEAR(band.entry(1, 1), std::sqrt(1e-6 * 1.0), 1e-15);
  EXPECT_NEAR(band.entry(2, 2), std::sqrt(1e-6 * 3.0), 1e-15);
  EXPECT_NEAR(band.entry(3, 3), std::sqrt(5.0), 1e-15);
  EXPECT_TRUE(solvesFinitely(band));
}

// The solves take a contiguous segment of a longer vector and touch nothing outside it.
TEST(BandedCholesky, SolvesASegmentInPlace) {
  std::mt19937 rng(23);
  BandMatrix m = randomSpd(9, 2, rng);
  ASSERT_EQ(m.band.factor(), 0);
  Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(9, -1.0, 2.0);
  Eigen::VectorXd longer = Eigen::VectorXd::Constant(13, 42.0);
  longer.segment(3, 9) = rhs;
  m.band.solveLower(longer.segment(3, 9));
  m.band.solveUpper(longer.segment(3, 9));
  EXPECT_LT((m.dense * longer.segment(3, 9) - rhs).norm(), 1e-12);
  for (const int i : {0, 1, 2, 12}) EXPECT_EQ(longer[i], 42.0);
}

}  // namespace
}  // namespace cyber::planner

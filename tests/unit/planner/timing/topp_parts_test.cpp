// The pieces of the time-optimal parameterisation, each against brute force: the banded
// Cholesky against a dense factorisation, the cone projection against its defining properties,
// the variable layout against a count of its slots,
// the limit rows against the drive model, the reachability profile against every row, the
// augmented Lagrangian's gradient against finite differences, its multiplier estimate against
// stationarity, and the solver from a cold start against the warm-started one.

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "math/banded_cholesky.hpp"
#include "math/second_order_cone.hpp"
#include "timing/topp_augmented_lagrangian.hpp"
#include "timing/topp_problem.hpp"
#include "timing/topp_reachability.hpp"
#include "topp_fixtures.hpp"

namespace cyber::planner {
namespace {

using testing::armDrive;
using testing::elevatorDrive;

TEST(BandedCholesky, MatchesDenseFactorisationOnRandomBandMatrices) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 5 + trial * 7;
    const int w = 1 + trial % 6;
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    BandedCholesky band;
    band.reset(n, w);
    for (int i = 0; i < n; ++i) {
      for (int j = std::max(0, i - w); j <= i; ++j) {
        const double v = i == j ? 2.0 * w + 1.0 + u(rng) : u(rng);  // diagonally dominant: SPD
        a(i, j) += v;
        if (i != j) a(j, i) += v;
        band.add(i, j, v);
      }
    }
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
  Eigen::VectorXd x = Eigen::VectorXd::Ones(3);
  band.solveLower(x);
  band.solveUpper(x);
  EXPECT_TRUE(x.allFinite());
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

// A sampled, normalised problem on the S-curve (q' of the arm changes sign).
topp::Problem makeProblem(int points, double b_start = 0.0) {
  const testing::WigglePath path(JointVector(0.2, 1.0), JointVector(1.5, 4.0), JointVector(0.05, 0.8), 3.0, 2.0);
  topp::Problem problem;
  problem.b_start = b_start;
  topp::sampleGrid(path, points, problem);
  topp::LimitMargins margins;
  margins.reset(problem.intervals());
  EXPECT_TRUE(topp::buildRows(testing::referenceDrives(), margins, problem, nullptr));
  problem.speed_bound = 1e3 / path.length();
  return problem;
}

TEST(ToppProblem, GridIsDenserWhereThePathBends) {
  const topp::Problem p = makeProblem(200);
  EXPECT_EQ(p.s.front(), 0.0);
  EXPECT_EQ(p.s.back(), 1.0);
  double smallest = 1.0, largest = 0.0;
  for (int k = 0; k < p.intervals(); ++k) {
    ASSERT_GT(p.ds(k), 0.0);
    smallest = std::min(smallest, p.ds(k));
    largest = std::max(largest, p.ds(k));
  }
  EXPECT_GT(largest / smallest, 1.5);
  // A straight line keeps a uniform grid.
  topp::Problem line;
  topp::sampleGrid(testing::LinePath(JointVector(0.0, 0.0), JointVector(1.0, 1.0)), 50, line);
  for (int k = 0; k < line.intervals(); ++k) EXPECT_NEAR(line.ds(k), 1.0 / 49.0, 1e-12);
}

// The time the profile (s, b linear in s between its nodes) takes from u0 to u1 on the grid.
double profileTime(const std::vector<double>& s, const std::vector<double>& b, double u0, double u1) {
  constexpr int kSteps = 64;
  auto speed = [&](double u) {
    const size_t k =
        std::min<size_t>(static_cast<size_t>(std::upper_bound(s.begin(), s.end(), u) - s.begin()), s.size() - 1);
    const size_t i = k == 0 ? 0 : k - 1;
    const double f = std::clamp((u - s[i]) / (s[i + 1] - s[i]), 0.0, 1.0);
    return std::sqrt((1.0 - f) * b[i] + f * b[i + 1]);
  };
  double t = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double a = u0 + (u1 - u0) * i / kSteps, c = u0 + (u1 - u0) * (i + 1) / kSteps;
    t += 2.0 * (c - a) / (speed(a) + speed(c));
  }
  return t;
}

TEST(ToppProblem, AProfileSpreadsTheGridInTime) {
  // Rest to rest on a line: even in s, the first and last intervals take far longer than the
  // middle ones; with the profile, 40 % of the points are even in time and the longest interval
  // shrinks, while the grid still spans [0, 1] in increasing order.
  const testing::LinePath path(JointVector(0.2, 1.0), JointVector(1.5, 4.0));
  topp::Problem even;
  even.speed_bound = 1e3 / path.length();
  topp::sampleGrid(path, 100, even);
  topp::LimitMargins margins;
  margins.reset(even.intervals());
  ASSERT_TRUE(topp::buildRows(testing::referenceDrives(), margins, even, nullptr));
  std::vector<double> b, controllable;
  ASSERT_EQ(topp::forwardBackward(even, b, controllable).status, topp::ReachabilityStatus::kOk);
  topp::Problem timed;
  topp::sampleGrid(path, 100, timed, topp::ProfileView{&even.s, &b});
  ASSERT_EQ(timed.gridPoints(), 100);
  EXPECT_EQ(timed.s.front(), 0.0);
  EXPECT_EQ(timed.s.back(), 1.0);
  auto longest = [&](const topp::Problem& p) {
    double t = 0.0;
    for (int k = 0; k < p.intervals(); ++k) {
      EXPECT_GT(p.ds(k), 0.0);
      t = std::max(t, profileTime(even.s, b, p.s[static_cast<size_t>(k)], p.s[static_cast<size_t>(k) + 1]));
    }
    return t;
  };
  EXPECT_LT(longest(timed), 0.6 * longest(even));
  EXPECT_LT(timed.ds(0), 0.5 * even.ds(0));
  EXPECT_LT(timed.ds(timed.intervals() - 1), 0.5 * even.ds(even.intervals() - 1));

  // A profile at constant speed takes equal time on equal lengths: the line's grid stays even.
  const std::vector<double> constant(even.s.size(), 1.0);
  topp::Problem steady;
  topp::sampleGrid(path, 50, steady, topp::ProfileView{&even.s, &constant});
  for (int k = 0; k < steady.intervals(); ++k) EXPECT_NEAR(steady.ds(k), 1.0 / 49.0, 1e-9);
}

// Each row at its sample point, for a given drive model: the volts or amps of that model's own
// volts() at random path speeds and accelerations (a line whose joints never change direction).
void expectRowsAreTheDriveModel(const DriveModel& drives) {
  const testing::LinePath path(JointVector(0.2, 1.0), JointVector(1.8, 4.0));
  topp::Problem p;
  p.b_start = 0.0;
  topp::sampleGrid(path, 20, p);
  topp::LimitMargins margins;
  margins.reset(p.intervals());
  ASSERT_TRUE(topp::buildRows(drives, margins, p, nullptr));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.1, 3.0), ua(-20.0, 20.0);
  const double length = path.length();
  int checked = 0;
  for (const topp::LinearRow& row : p.rows) {
    if (row.interval == 0 && row.at == 0.0) continue;  // pinned at rest: Coulomb band, checked elsewhere
    if (row.kind != topp::LimitKind::kVoltage && row.kind != topp::LimitKind::kCurrent) continue;
    const double s = (p.s[static_cast<size_t>(row.interval)] + row.at * p.ds(row.interval)) * length;
    const PathPoint pt = path.at(s);
    const DriveParams& d = drives.drive(row.joint);
    // Physical speed sdot and path acceleration sddot; the problem's b = sdot^2 / L^2, a = sddot / L.
    const double sdot = u(rng), sddot = ua(rng);
    const double b = sdot * sdot / (length * length), a = sddot / length, c = std::sqrt(b);
    const JointVector qdot = pt.dq_ds * sdot;
    const JointVector qddot = pt.d2q_ds2 * sdot * sdot + pt.dq_ds * sddot;
    const double v = drives.volts(pt.q, qdot, qddot)[row.joint];
    const double scale =
        row.kind == topp::LimitKind::kVoltage ? d.voltage_limit_volts : d.motor.resistanceOhms() * d.current_limit_amps;
    const double value = row.value(a, b, b, c, c) * scale;  // b, c equal at both nodes: the sample's own
    const double physical =
        row.kind == topp::LimitKind::kVoltage
            ? v
            : drives.amps(drives.volts(pt.q, qdot, qddot), qdot)[row.joint] * d.motor.resistanceOhms();
    // value = physical - (constant terms), the constants sit in the bounds: compare the bounds.
    EXPECT_NEAR(row.hi * scale - value,
                (row.kind == topp::LimitKind::kVoltage ? d.voltage_limit_volts : scale) - physical,
                1e-9 * (1.0 + std::abs(physical)));
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(ToppProblem, RowsAreTheFeedforwardAtTheirSamplePoints) { expectRowsAreTheDriveModel(testing::referenceDrives()); }

// The coupled model: a double-jointed arm whose shoulder load depends on the elbow.
TEST(ToppProblem, RowsAreTheRigidBodyDynamicsAtTheirSamplePoints) {
  JointChain chain;
  chain[0] = ChainJoint{"shoulder", JointType::kRevolute, Point2(0.0, 0.654), 0.0, {0.0, 3.2}};
  chain[1] = ChainJoint{"elbow", JointType::kRevolute, Point2(0.686, 0.0), 0.0, {0.5, 5.8}};
  const std::array<LinkInertia, kJointCount> bodies{LinkInertia{1.036, Point2(0.4318, 0.0), 0.08},
                                                    LinkInertia{3.76, Point2(0.769, 0.02), 0.28}};
  DriveParams shoulder = testing::armDrive();
  shoulder.kS_volts = 0.2;
  shoulder.gearing = 197.0;
  DriveParams elbow = testing::armDrive();
  elbow.gearing = 200.0;
  expectRowsAreTheDriveModel(DriveModel({shoulder, elbow}, ChainDynamics(chain, bodies)));
}

TEST(ToppReachability, ProfileSatisfiesEveryRowAndIsControllable) {
  const topp::Problem p = makeProblem(150);
  std::vector<double> b, controllable;
  const topp::ReachabilityResult r = topp::forwardBackward(p, b, controllable);
  ASSERT_EQ(r.status, topp::ReachabilityStatus::kOk) << r.reason;
  EXPECT_EQ(b.front(), 0.0);
  EXPECT_EQ(b.back(), 0.0);
  for (int k = 0; k < p.intervals(); ++k) {
    EXPECT_LE(b[static_cast<size_t>(k)], controllable[static_cast<size_t>(k)] * (1 + 1e-9) + 1e-12);
    const double a = (b[static_cast<size_t>(k) + 1] - b[static_cast<size_t>(k)]) / (2.0 * p.ds(k));
    const double c0 = std::sqrt(b[static_cast<size_t>(k)]), c1 = std::sqrt(b[static_cast<size_t>(k) + 1]);
    for (int i = p.row_begin[static_cast<size_t>(k)]; i < p.row_begin[static_cast<size_t>(k) + 1]; ++i) {
      const topp::LinearRow& row = p.rows[static_cast<size_t>(i)];
      const double v = row.value(a, b[static_cast<size_t>(k)], b[static_cast<size_t>(k) + 1], c0, c1);
      EXPECT_LE(v, row.hi + 1e-7) << "interval " << k << " at " << row.at;
      EXPECT_GE(v, row.lo - 1e-7) << "interval " << k << " at " << row.at;
    }
  }
  // A start faster than C_0 is reported as such.
  topp::Problem fast = makeProblem(150, 1.5 * r.controllable_start_b);
  EXPECT_EQ(topp::forwardBackward(fast, b, controllable).status, topp::ReachabilityStatus::kStartNotControllable);
  EXPECT_EQ(topp::forwardBackward(fast, b, controllable, 0.2).status, topp::ReachabilityStatus::kStartNotControllable);
  // Within the start tolerance it starts from C_0 (the edge of the controllable set) instead.
  // (C_0 of a moving start: a start at rest pins the first node to qdot = 0, which changes its rows.)
  const double edge =
      topp::forwardBackward(makeProblem(150, 0.5 * r.controllable_start_b), b, controllable).controllable_start_b;
  topp::Problem near_edge = makeProblem(150, 1.01 * 1.01 * edge);
  EXPECT_EQ(topp::forwardBackward(near_edge, b, controllable, 0.005).status,
            topp::ReachabilityStatus::kStartNotControllable);
  const topp::ReachabilityResult clamped = topp::forwardBackward(near_edge, b, controllable, 0.02);
  ASSERT_EQ(clamped.status, topp::ReachabilityStatus::kOk);
  EXPECT_EQ(clamped.start_b, clamped.controllable_start_b);
  EXPECT_EQ(b.front(), clamped.controllable_start_b);
}

// Each node's controllable speed is the top of the speeds from which the node after can be reached
// within its own controllable speed: every speed up to it can (scanned), and a speed 10^-4 above
// it cannot (fastestNextSpeed, checked against a scan below, answers "can").
TEST(ToppReachability, ControllableSpeedIsTheTopOfTheStoppableSpeedsAtEveryNode) {
  for (const double b_start : {0.0, 0.5}) {
    const topp::Problem p = makeProblem(150, b_start);
    std::vector<double> b, controllable;
    ASSERT_EQ(topp::forwardBackward(p, b, controllable).status, topp::ReachabilityStatus::kOk);
    int capped = 0;
    for (int k = 0; k < p.intervals(); ++k) {
      const double c_top = std::sqrt(controllable[static_cast<size_t>(k)]);
      const double c_next = std::sqrt(controllable[static_cast<size_t>(k) + 1]);
      auto stoppable = [&](double c) { return topp::fastestNextSpeed(p, k, c, c_next) >= 0.0; };
      for (int i = 0; i <= 50; ++i) EXPECT_TRUE(stoppable(c_top * i / 50)) << "node " << k << ", " << i << "/50";
      if (c_top < 0.99 * p.speed_bound) {
        ++capped;
        EXPECT_FALSE(stoppable(c_top * (1.0 + 1e-4) + 1e-9)) << "node " << k << ": C_k could be larger";
      }
    }
    EXPECT_GT(capped, 100);
  }
}

// The largest next speed against a dense scan of [0, c_max] (the rows' feasible set can be a
// union of intervals, so the scan looks at all of it): the answer satisfies every row, and no
// scanned speed above it does.
TEST(ToppReachability, FastestNextSpeedIsTheLargestFeasibleOverSeededStates) {
  const topp::Problem p = makeProblem(150);
  std::vector<double> b, controllable;
  ASSERT_EQ(topp::forwardBackward(p, b, controllable).status, topp::ReachabilityStatus::kOk);
  auto within = [&](int k, double c0, double c1, double tolerance) {
    const double b0 = c0 * c0, b1 = c1 * c1, a = (b1 - b0) / (2.0 * p.ds(k));
    for (int i = p.row_begin[static_cast<size_t>(k)]; i < p.row_begin[static_cast<size_t>(k) + 1]; ++i) {
      const topp::LinearRow& row = p.rows[static_cast<size_t>(i)];
      const double v = row.value(a, b0, b1, c0, c1);
      if (v > row.hi + tolerance || v < row.lo - tolerance) return false;
    }
    return true;
  };
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> interval(0, p.intervals() - 1);
  std::uniform_real_distribution<double> fraction(0.0, 1.3);
  int found = 0, none = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int k = interval(rng);
    const double c_cap = std::sqrt(std::max(controllable[static_cast<size_t>(k)], 1e-6));
    const double c_now = fraction(rng) * c_cap;
    const double c_max = fraction(rng) * std::sqrt(std::max(controllable[static_cast<size_t>(k) + 1], 1e-6));
    const double c_next = topp::fastestNextSpeed(p, k, c_now, c_max);
    constexpr int kScan = 4000;
    double scanned = -1.0;
    for (int i = kScan; i >= 0; --i) {
      const double c = c_max * i / kScan;
      if (within(k, c_now, c, 0.0)) {
        scanned = c;
        break;
      }
    }
    if (c_next < 0.0) {
      ++none;
      EXPECT_LT(scanned, 0.0) << "trial " << trial << ": none found, but " << scanned << " is feasible";
      continue;
    }
    ++found;
    EXPECT_LE(c_next, c_max) << "trial " << trial;
    EXPECT_TRUE(within(k, c_now, c_next, 1e-9)) << "trial " << trial << " c_next " << c_next;
    EXPECT_LE(scanned, c_next * (1.0 + 1e-9) + 1e-12) << "trial " << trial << ": " << scanned << " above " << c_next;
  }
  EXPECT_GT(found, 200);
  EXPECT_GT(none, 10);
}

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

TEST(ToppAugmentedLagrangian, GradientMatchesFiniteDifferences) {
  topp::Problem p = makeProblem(40);
  std::vector<double> b, controllable;
  ASSERT_EQ(topp::forwardBackward(p, b, controllable).status, topp::ReachabilityStatus::kOk);
  Eigen::VectorXd x;
  topp::initialGuess(p, b, x);
  topp::Multipliers m;
  topp::estimateMultipliers(p, x, m);
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

TEST(ToppAugmentedLagrangian, EstimatedMultipliersMakeTheWarmStartNearlyStationary) {
  topp::Problem p = makeProblem(120);
  std::vector<double> b, controllable;
  ASSERT_EQ(topp::forwardBackward(p, b, controllable).status, topp::ReachabilityStatus::kOk);
  Eigen::VectorXd x;
  topp::initialGuess(p, b, x);
  topp::Multipliers estimated, zero;
  EXPECT_GT(topp::estimateMultipliers(p, x, estimated), 0);
  zero.reset(p);
  Eigen::VectorXd g_estimated(x.size()), g_zero(x.size());
  topp::augmentedLagrangian(p, estimated, 1e3, x, g_estimated);
  topp::augmentedLagrangian(p, zero, 1e3, x, g_zero);
  // The multipliers balance (most of) the cost gradient at the reachability profile.
  EXPECT_LT(g_estimated.lpNorm<1>(), 0.2 * g_zero.lpNorm<1>());
  for (Eigen::Index i = 0; i < estimated.row_upper.size(); ++i) {
    EXPECT_GE(estimated.row_upper[i], 0.0);
    EXPECT_GE(estimated.row_lower[i], 0.0);
  }
}

TEST(ToppAugmentedLagrangian, ColdStartReachesTheSameOptimumAsTheWarmStart) {
  topp::Problem p = makeProblem(60);
  std::vector<double> b, controllable;
  ASSERT_EQ(topp::forwardBackward(p, b, controllable).status, topp::ReachabilityStatus::kOk);
  topp::AlSettings settings;
  settings.max_outer_iterations = 200;
  settings.max_inner_iterations = 2000;

  topp::AlState warm;
  topp::initialGuess(p, b, warm.x);
  topp::estimateMultipliers(p, warm.x, warm.multipliers);
  topp::AlWorkspace workspace;
  const topp::AlReport w = topp::solveAugmentedLagrangian(p, settings, warm, workspace);
  ASSERT_TRUE(w.converged);

  // Cold: zero multipliers, the reachability profile slowed down to 80 %.
  topp::AlState cold;
  std::vector<double> slow = b;
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

}  // namespace
}  // namespace cyber::planner

// The discretised problem (topp_problem.hpp): its grid against the path's bends and a speed
// profile's time, its limit rows against the drive model's volts and amps at their sample points
// for both kinds of drive, the limits that no motion can meet, and the change of time unit.

#include "timing/topp_problem.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "timing/topp_reachability.hpp"
#include "topp_fixtures.hpp"

namespace cyber::planner {
namespace {

TEST(ToppProblem, GridIsDenserWhereThePathBends) {
  const topp::Problem p = testing::wiggleProblem(200);
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
  topp::sampleGrid(testing::LinePath(JointVector{{0.0, 0.0}}, JointVector{{1.0, 1.0}}), 50, line);
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
  const testing::LinePath path(JointVector{{0.2, 1.0}}, JointVector{{1.5, 4.0}});
  topp::Problem even;
  even.speed_bound = 1e3 / path.length();
  topp::sampleGrid(path, 100, even);
  topp::LimitMargins margins;
  margins.reset(even.intervals());
  ASSERT_TRUE(topp::buildRows(testing::referenceDrives(), margins, even));
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
  const testing::LinePath path(JointVector{{0.2, 1.0}}, JointVector{{1.8, 4.0}});
  topp::Problem p;
  p.b_start = 0.0;
  topp::sampleGrid(path, 20, p);
  topp::LimitMargins margins;
  margins.reset(p.intervals());
  ASSERT_TRUE(topp::buildRows(drives, margins, p));
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
  JointChain chain(2);
  chain[0] = ChainJoint{"shoulder", JointType::kRevolute, Point2(0.0, 0.654), 0.0, {0.0, 3.2}};
  chain[1] = ChainJoint{"elbow", JointType::kRevolute, Point2(0.686, 0.0), 0.0, {0.5, 5.8}};
  const PerJoint<LinkInertia> bodies{LinkInertia{1.036, Point2(0.4318, 0.0), 0.08},
                                     LinkInertia{3.76, Point2(0.769, 0.02), 0.28}};
  DriveParams shoulder = testing::armDrive();
  shoulder.kS_volts = 0.2;
  shoulder.gearing = 197.0;
  DriveParams elbow = testing::armDrive();
  elbow.gearing = 200.0;
  expectRowsAreTheDriveModel(DriveModel({shoulder, elbow}, ChainDynamics(chain, bodies)));
}

// A joint that does not move along the path still needs its gravity term: held by more than its
// limits allow it cannot hold whatever the motion, and the error says which limit and where.
TEST(ToppProblem, ALimitNoMotionCanMeetIsRefusedWithItsPlace) {
  const testing::LinePath arm_only(JointVector{{1.0, 1.0}}, JointVector{{1.0, 3.0}});
  topp::Problem p;
  topp::sampleGrid(arm_only, 20, p);
  topp::LimitMargins margins;
  margins.reset(p.intervals());
  auto refusal = [&](const DriveParams& elevator) {
    const auto built = topp::buildRows(testing::drivesOf(elevator, testing::armDrive()), margins, p);
    if (built) return std::string();
    EXPECT_EQ(built.status(), PlanStatus::kInvalidInput);
    return built.error().message;
  };
  DriveParams heavy = testing::elevatorDrive();
  heavy.kG_volts = 12.5;  // above the 12 V limit
  EXPECT_EQ(refusal(heavy), "the voltage limit of joint 0 cannot hold at s = 0.0000 whatever the motion");
  // Within the voltage, but more than the current limit times R (about 2 V) at rest.
  heavy.kG_volts = 5.0;
  EXPECT_EQ(refusal(heavy), "the current limit of joint 0 cannot hold at s = 0.0000 whatever the motion");
  // Just within both (kS at rest counts too), the joint is held.
  heavy.kG_volts = heavy.motor.resistanceOhms() * heavy.current_limit_amps - heavy.kS_volts - 1e-9;
  EXPECT_EQ(refusal(heavy), "");
  // A margin that lowers the current limit of one interval refuses it again, there.
  margins.at(7, 0, topp::LimitKind::kCurrent) = 0.01;
  char where[64];
  std::snprintf(where, sizeof where, "at s = %.4f whatever", p.s[7]);
  const std::string error = refusal(heavy);
  EXPECT_NE(error.find("the current limit of joint 0"), std::string::npos) << error;
  EXPECT_NE(error.find(where), std::string::npos) << error;
}

// The same motion in another time unit: a, b scale by T^2 and c by T, so every row reads the same
// value; the boundary speeds and the speed bound follow, the grid and the rows' layout do not move.
TEST(ToppProblem, ScalingTimeKeepsEveryRowsValueForTheSameMotion) {
  const topp::Problem p = testing::wiggleProblem(60, 0.3);
  topp::Problem scaled;
  const double t = 0.37;
  topp::scaleTime(p, t, scaled);
  EXPECT_EQ(scaled.s, p.s);
  EXPECT_EQ(scaled.row_begin, p.row_begin);
  EXPECT_TRUE(scaled.points.empty());
  ASSERT_EQ(scaled.rows.size(), p.rows.size());
  EXPECT_DOUBLE_EQ(scaled.b_start, p.b_start * t * t);
  EXPECT_DOUBLE_EQ(scaled.b_end, p.b_end * t * t);
  EXPECT_DOUBLE_EQ(scaled.speed_bound, p.speed_bound * t);
  EXPECT_EQ(scaled.cost_scale, p.cost_scale);
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-3.0, 3.0), positive(0.0, 4.0);
  for (size_t i = 0; i < p.rows.size(); ++i) {
    const topp::LinearRow& row = p.rows[i];
    const topp::LinearRow& out = scaled.rows[i];
    EXPECT_EQ(out.lo, row.lo);
    EXPECT_EQ(out.hi, row.hi);
    EXPECT_EQ(out.kind, row.kind);
    const double a = u(rng), b0 = positive(rng), b1 = positive(rng);
    const double c0 = std::sqrt(b0), c1 = std::sqrt(b1);
    EXPECT_NEAR(out.value(a * t * t, b0 * t * t, b1 * t * t, c0 * t, c1 * t), row.value(a, b0, b1, c0, c1),
                1e-12 * (1.0 + std::abs(row.value(a, b0, b1, c0, c1))))
        << "row " << i;
  }
}

}  // namespace
}  // namespace cyber::planner

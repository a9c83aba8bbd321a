// Whether a trajectory's sampled columns agree (columnConsistency, trajectory.hpp) against closed
// forms: zero where the trapezoid is exact (constant path acceleration on a line); for a
// bang-bang motion the trapezoid's own error across its one switch; and for a path whose
// derivatives lie (q' too long, a curvature on a straight line) the share by which the integrals
// miss, measured to the last instant even when the step does not divide the duration.

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cyber/planner/trajectory.hpp"
#include "topp_fixtures.hpp"

namespace cyber::planner {
namespace {

const JointVector kFrom{{0.3, 1.0}}, kTo{{1.1, 3.5}};

// A straight line q = from + s u whose reported derivatives are q' = scale u and q'' = curvature:
// the truth for scale 1 and curvature 0.
class MisreportedLine final : public GeometricPath {
 public:
  MisreportedLine(double scale, const JointVector& curvature) : scale_(scale), curvature_(curvature) {}
  [[nodiscard]] double length() const override { return line_.length(); }
  [[nodiscard]] PathPoint at(double s) const override {
    PathPoint p = line_.at(s);
    p.dq_ds *= scale_;
    p.d2q_ds2 = curvature_;
    return p;
  }
  [[nodiscard]] JointVector direction() const { return line_.at(0.0).dq_ds; }

 private:
  testing::LinePath line_{kFrom, kTo};
  double scale_;
  JointVector curvature_;
};

Trajectory timed(std::shared_ptr<const GeometricPath> path, std::vector<double> s_fractions, std::vector<double> b) {
  const double length = path->length();
  for (double& s : s_fractions) s *= length;
  auto t = Trajectory::create(std::move(path), testing::referenceDrives(), std::move(s_fractions), std::move(b));
  EXPECT_TRUE(t.ok()) << t.error().message;
  return std::move(t).value();
}

std::shared_ptr<const GeometricPath> truthful() { return std::make_shared<MisreportedLine>(1.0, JointVector::Zero(2)); }

// Constant path acceleration on a line: every column is linear or quadratic in time, and the
// trapezoid integrates a linear velocity exactly; so does it a constant acceleration.
TEST(ColumnConsistency, IsZeroWhereTheTrapezoidIsExact) {
  const Trajectory braking = timed(truthful(), {0.0, 1.0}, {2.0, 0.0});
  // The same constant deceleration over many grid points: b linear in s throughout.
  const Trajectory uneven = timed(truthful(), {0.0, 0.1, 0.15, 0.6, 1.0}, {2.0, 1.8, 1.7, 0.8, 0.0});
  for (const Trajectory* t : {&braking, &uneven}) {
    for (const double step : {1e-3, t->duration_s() / 7.3, t->duration_s() / 2.0}) {
      const ColumnConsistency c = columnConsistency(*t, step);
      EXPECT_LT(c.position_error, 1e-12) << "step " << step;
      EXPECT_LT(c.velocity_error, 1e-12) << "step " << step;
    }
  }
  // A joint that does not move is measured against a floor, never divided by zero.
  const auto elevator_only = std::make_shared<testing::LinePath>(kFrom, JointVector{{kTo.x(), kFrom.y()}});
  const ColumnConsistency still = columnConsistency(timed(elevator_only, {0.0, 1.0}, {2.0, 0.0}), 1e-3);
  EXPECT_LT(still.position_error, 1e-12);
  EXPECT_LT(still.velocity_error, 1e-12);
}

// Rest to rest at path acceleration +a then -a, switching at T/2 a quarter of a step past a
// sample (h = T / 10.5): across that step the trapezoid misses the velocity by 2 a h |1/4 - 1/2|
// and the position by a alpha beta (alpha = h / 4, beta = 3 h / 4, the parts of the step either
// side of the switch); after it both integrals are exact again. Relative to the fastest sample,
// a 5 h, and the travel a T^2 / 4: 0.1 and 0.75 h^2 / T^2. With the switch on a sample, that
// sample reads the acceleration of one side: the velocity's trapezoid misses by half the jump
// times the step (0.2 of the peak speed a 5 h) while the position's is exact.
TEST(ColumnConsistency, IsTheTrapezoidsErrorAcrossABangBangSwitch) {
  const Trajectory t = timed(truthful(), {0.0, 0.5, 1.0}, {0.0, 3.0, 0.0});
  const double duration = t.duration_s();
  EXPECT_NEAR(duration, 2.0 * t.path().length() / std::sqrt(3.0), 1e-12);
  const ColumnConsistency c = columnConsistency(t, duration / 10.5);
  EXPECT_NEAR(c.velocity_error, 0.1, 1e-9);
  EXPECT_NEAR(c.position_error, 0.75 / (10.5 * 10.5), 1e-9);
  const ColumnConsistency on = columnConsistency(t, duration / 10.0);
  EXPECT_NEAR(on.velocity_error, 0.2, 1e-9);
  EXPECT_LT(on.position_error, 1e-9);
}

// q' reported 10 % too long: the velocities integrate to 110 % of the travel by the end, so the
// position error is 0.1 (measured at the last instant, 0.37 steps after the last whole one),
// and the accelerations still integrate to the velocities.
TEST(ColumnConsistency, ATangentTooLongMissesThePositionsByItsExcess) {
  const Trajectory t = timed(std::make_shared<MisreportedLine>(1.1, JointVector::Zero(2)), {0.0, 1.0}, {2.0, 0.0});
  const double step = t.duration_s() / 12.37;
  const ColumnConsistency c = columnConsistency(t, step);
  EXPECT_NEAR(c.position_error, 0.1, 1e-9);
  EXPECT_LT(c.velocity_error, 1e-12);
}

// A curvature w on a straight line adds w b to every acceleration and nothing to the velocities:
// the accelerations' integral overshoots by w times the integral of b = sdot^2 over time, which
// braking from b0 to rest over L makes (2/3) sqrt(b0) L; relative to the peak speed |u_j| sqrt(b0)
// of joint j that is (2/3) L |w_j| / |u_j|. The positions are not affected.
TEST(ColumnConsistency, ACurvatureOnALineMissesTheVelocitiesByItsIntegral) {
  const JointVector w{{0.01, -0.02}};
  const auto path = std::make_shared<MisreportedLine>(1.0, w);
  const Trajectory t = timed(path, {0.0, 1.0}, {2.0, 0.0});
  const double length = path->length();
  const JointVector u = path->direction();
  const double expected =
      std::max(2.0 / 3.0 * length * std::abs(w[0] / u[0]), 2.0 / 3.0 * length * std::abs(w[1] / u[1]));
  const ColumnConsistency c = columnConsistency(t, t.duration_s() / 2000.5);
  EXPECT_NEAR(c.velocity_error, expected, 1e-5 * expected);
  EXPECT_LT(c.position_error, 1e-12);
}

}  // namespace
}  // namespace cyber::planner

// Trajectory: validation, the exact constant-acceleration kinematics between grid points, the
// time map and its inverse, and sample() without heap allocation (the 200 Hz streamer calls it).

#include "cyber/planner/trajectory.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"

#include "reference_model.hpp"
#include "topp_fixtures.hpp"

namespace cyber::planner {
namespace {

using testing::armDrive;
using testing::drivesOf;
using testing::elevatorDrive;
using testing::LinePath;
using testing::referenceDrives;
using testing::WigglePath;

std::shared_ptr<const GeometricPath> wiggle() {
  return std::make_shared<WigglePath>(JointVector{{0.2, 1.0}}, JointVector{{1.5, 4.0}}, JointVector{{0.05, 0.8}}, 2.0,
                                      2.0);
}

// An arbitrary valid profile: up, along, down, with uneven spacing.
Trajectory makeTrajectory(std::shared_ptr<const GeometricPath> path) {
  const double l = path->length();
  std::vector<double> s{0.0, 0.1 * l, 0.25 * l, 0.5 * l, 0.8 * l, 0.95 * l, l};
  std::vector<double> b{0.0, 0.8, 2.0, 2.5, 1.5, 0.4, 0.0};
  return Trajectory::create(std::move(path), referenceDrives(), s, b).value();
}

TEST(Trajectory, InvalidProfilesAreTypedErrors) {
  const auto path = std::make_shared<LinePath>(JointVector{{0.0, 0.0}}, JointVector{{1.0, 0.0}});
  auto make = [&](std::vector<double> s, std::vector<double> b) {
    return Trajectory::create(path, referenceDrives(), std::move(s), std::move(b)).status();
  };
  EXPECT_EQ(Trajectory::create(nullptr, referenceDrives(), {0.0, 1.0}, {0.0, 0.0}).status(), PlanStatus::kInvalidInput);
  EXPECT_EQ(make({}, {}), PlanStatus::kInvalidInput);
  EXPECT_EQ(make({0.0, 1.0}, {0.0}), PlanStatus::kInvalidInput);
  EXPECT_EQ(make({0.0, 0.5}, {0.0, 1.0}), PlanStatus::kInvalidInput);                      // does not reach the end
  EXPECT_EQ(make({0.0, 0.6, 0.6, 1.0}, {0.0, 1.0, 1.0, 0.0}), PlanStatus::kInvalidInput);  // not increasing
  EXPECT_EQ(make({0.0, 0.5, 1.0}, {0.0, -1.0, 0.0}), PlanStatus::kInvalidInput);           // negative b
  EXPECT_EQ(make({0.0, 0.5, 1.0}, {0.0, NAN, 0.0}), PlanStatus::kInvalidInput);
  EXPECT_EQ(make({0.0, 0.5, 1.0}, {0.0, 0.0, 1.0}), PlanStatus::kInvalidInput);  // at rest over an interval
  EXPECT_EQ(make({0.0, 0.5, 1.0}, {0.0, 1.0, 0.0}), PlanStatus::kOk);
}

TEST(Trajectory, DurationIsTheExactSumOverIntervals) {
  const auto path = wiggle();
  const Trajectory t = makeTrajectory(path);
  double expected = 0.0;
  for (size_t k = 0; k + 1 < t.sGrid().size(); ++k) {
    expected += 2.0 * (t.sGrid()[k + 1] - t.sGrid()[k]) / (std::sqrt(t.bGrid()[k]) + std::sqrt(t.bGrid()[k + 1]));
  }
  EXPECT_NEAR(t.duration_s(), expected, 1e-12);
}

TEST(Trajectory, ConstantPathAccelerationBetweenGridPoints) {
  const auto path = wiggle();
  const Trajectory t = makeTrajectory(path);
  for (int i = 0; i <= 1000; ++i) {
    const double time = t.duration_s() * i / 1000.0;
    const TrajectorySample s = t.sample(time);
    // b = sdot^2 is linear in s on each interval: the interpolated grid value.
    size_t k = 0;
    while (k + 2 < t.sGrid().size() && t.sGrid()[k + 1] <= s.s) ++k;
    const double u = (s.s - t.sGrid()[k]) / (t.sGrid()[k + 1] - t.sGrid()[k]);
    EXPECT_NEAR(s.sdot * s.sdot, (1.0 - u) * t.bGrid()[k] + u * t.bGrid()[k + 1], 1e-9);
    // sddot is the interval's constant (b_{k+1} - b_k) / (2 ds).
    EXPECT_NEAR(s.sddot, (t.bGrid()[k + 1] - t.bGrid()[k]) / (2.0 * (t.sGrid()[k + 1] - t.sGrid()[k])), 1e-9);
    // Chain rule (eq. 11): qdot = q' sdot, qddot = q'' sdot^2 + q' sddot.
    const PathPoint p = path->at(s.s);
    EXPECT_LT((s.q - p.q).norm(), 1e-12);
    EXPECT_LT((s.qdot - p.dq_ds * s.sdot).norm(), 1e-12);
    EXPECT_LT((s.qddot - (p.d2q_ds2 * s.sdot * s.sdot + p.dq_ds * s.sddot)).norm(), 1e-9);
  }
}

TEST(Trajectory, DerivativesMatchFiniteDifferencesInsideIntervals) {
  const auto path = wiggle();
  const Trajectory t = makeTrajectory(path);
  const double h = 1e-6;
  for (int i = 1; i < 200; ++i) {
    const double time = t.duration_s() * (i + 0.37) / 200.0;
    const TrajectorySample a = t.sample(time - h);
    const TrajectorySample b = t.sample(time + h);
    const TrajectorySample m = t.sample(time);
    if (t.pathParameterAt(time - h) < t.sGrid()[1] && t.pathParameterAt(time + h) > t.sGrid()[1]) continue;
    EXPECT_LT(((b.q - a.q) / (2 * h) - m.qdot).norm(), 1e-5) << time;
    EXPECT_LT(((b.qdot - a.qdot) / (2 * h) - m.qddot).norm(), 1e-3 * (1.0 + m.qddot.norm())) << time;
  }
}

TEST(Trajectory, TimeMapAndItsInverseAgree) {
  const Trajectory t = makeTrajectory(wiggle());
  for (int i = 0; i <= 500; ++i) {
    const double time = t.duration_s() * i / 500.0;
    // Near a stop (sdot -> 0) a roundoff in s is a larger error in t (t ~ sqrt(s)): 1e-7 s.
    EXPECT_NEAR(t.timeAt(t.pathParameterAt(time)), time, 1e-7);
    EXPECT_NEAR(t.sample(time).s, t.pathParameterAt(time), 1e-12);
  }
  for (size_t k = 0; k < t.sGrid().size(); ++k) EXPECT_NEAR(t.timeAt(t.sGrid()[k]), t.tGrid()[k], 1e-12);
  EXPECT_EQ(t.timeAt(-1.0), 0.0);
  EXPECT_NEAR(t.timeAt(1e9), t.duration_s(), 1e-12);
}

TEST(Trajectory, EndsAndOutOfRangeTimes) {
  const auto path = wiggle();
  const Trajectory t = makeTrajectory(path);
  const TrajectorySample before = t.sample(-3.0);
  EXPECT_EQ(before.t, 0.0);
  EXPECT_EQ(before.q, path->at(0.0).q);
  EXPECT_EQ(before.qdot, JointVector::Zero(2));
  const TrajectorySample end = t.sample(t.duration_s());
  EXPECT_LT((end.q - path->at(path->length()).q).norm(), 1e-9);
  EXPECT_LT(end.qdot.norm(), 1e-6);
  // After the end the goal is held at rest (gravity feedforward only).
  const TrajectorySample after = t.sample(t.duration_s() + 1.0);
  EXPECT_LT((after.q - path->at(path->length()).q).norm(), 1e-12);
  EXPECT_EQ(after.qdot, JointVector::Zero(2));
  EXPECT_EQ(after.qddot, JointVector::Zero(2));
  EXPECT_NEAR(after.volts[test::kElevator], elevatorDrive().kG_volts, 1e-12);
  const TrajectorySample nan = t.sample(std::nan(""));
  EXPECT_TRUE(nan.q.allFinite());
}

TEST(Trajectory, VoltsAndAmpsFollowTheDriveModel) {
  const Trajectory t = makeTrajectory(wiggle());
  for (int i = 0; i <= 100; ++i) {
    const TrajectorySample s = t.sample(t.duration_s() * i / 100.0);
    EXPECT_DOUBLE_EQ(s.volts[test::kArm], armDrive().volts(s.q[test::kArm], s.qdot[test::kArm], s.qddot[test::kArm]));
    EXPECT_DOUBLE_EQ(s.amps[test::kArm], armDrive().amps(s.volts[test::kArm], s.qdot[test::kArm]));
    EXPECT_DOUBLE_EQ(s.volts[test::kElevator],
                     elevatorDrive().volts(s.q[test::kElevator], s.qdot[test::kElevator], s.qddot[test::kElevator]));
  }
}

// The largest |volts| / limit of a joint over samples `step` apart and the last, by brute force.
double peakVoltageRatio(const Trajectory& t, int joint, double step) {
  double peak = 0.0;
  for (double time = 0.0;; time += step) {
    const TrajectorySample s = t.sample(std::min(time, t.duration_s()));
    peak = std::max(peak, std::abs(s.volts[joint]) / t.drive(joint).voltage_limit_volts);
    if (time >= t.duration_s()) return peak;
  }
}

TEST(Trajectory, WithinDriveLimitsJudgesEverySampleAgainstTheTolerance) {
  const auto path = wiggle();
  const Trajectory reference = makeTrajectory(path);
  const double step = 0.001;
  const double peak = peakVoltageRatio(reference, test::kArm, step);
  ASSERT_GT(peak, 0.0);
  // The same profile with the arm's voltage limit just above and just below its peak.
  auto withArmLimit = [&](double volts) {
    DriveParams arm = armDrive();
    arm.voltage_limit_volts = volts;
    arm.current_limit_amps = 1e6;
    DriveParams elevator = elevatorDrive();
    elevator.voltage_limit_volts = elevator.current_limit_amps = 1e6;
    return Trajectory::create(path, drivesOf(elevator, arm), reference.sGrid(), reference.bGrid()).value();
  };
  const double limit = armDrive().voltage_limit_volts * peak;
  EXPECT_TRUE(withinDriveLimits(withArmLimit(1.001 * limit), step, 0.0));
  EXPECT_FALSE(withinDriveLimits(withArmLimit(0.99 * limit), step, 0.0));
  EXPECT_TRUE(withinDriveLimits(withArmLimit(0.99 * limit), step, 0.02));
  DriveParams capped = armDrive();
  capped.voltage_limit_volts = capped.current_limit_amps = 1e6;
  capped.acceleration_limit = 1e-3;
  EXPECT_FALSE(withinDriveLimits(
      Trajectory::create(path, drivesOf(elevatorDrive(), capped), reference.sGrid(), reference.bGrid()).value(), step,
      0.0));
}

// The speed along the path at s (sqrt(b)).
double speedAt(const Trajectory& t, double s) { return t.sample(t.timeAt(s)).sdot; }

TEST(Trajectory, AGentlerStartAcceleratesLessThenJoinsTheSameProfile) {
  const Trajectory t = makeTrajectory(wiggle());
  const double l = t.path().length();
  const double scale = 0.9;
  const auto gentler = gentlerStart(t, scale);
  ASSERT_TRUE(gentler.ok());
  const Trajectory& g = gentler.value();
  EXPECT_NEAR(g.sample(0.0).sddot, scale * t.sample(0.0).sddot, 1e-12);
  EXPECT_GT(g.duration_s(), t.duration_s());
  // The line 7.2 s / l meets the profile between 0.25 l and 0.5 l: slower before, the same after.
  for (int i = 1; i <= 100; ++i) {
    const double s = l * i / 100.0;
    EXPECT_LE(speedAt(g, s), speedAt(t, s) + 1e-12) << s;
    if (s >= 0.5 * l) {
      EXPECT_NEAR(speedAt(g, s), speedAt(t, s), 1e-9) << s;
    }
    if (s <= 0.25 * l) {
      EXPECT_LT(speedAt(g, s), speedAt(t, s)) << s;
    }
  }
  // The same path: positions by s agree.
  const TrajectorySample end = g.sample(g.duration_s());
  EXPECT_NEAR((end.q - t.sample(t.duration_s()).q).norm(), 0.0, 1e-12);
  EXPECT_NEAR(gentlerStart(t, 1.0).value().duration_s(), t.duration_s(), 1e-12);
  for (double bad : {0.0, -0.5, 1.5, static_cast<double>(NAN)}) {
    EXPECT_EQ(gentlerStart(t, bad).status(), PlanStatus::kInvalidInput) << bad;
  }
  // Only from rest.
  const auto moving = Trajectory::create(t.sharedPath(), referenceDrives(), {0.0, 0.5 * l, l}, {1.0, 2.0, 0.0});
  ASSERT_TRUE(moving.ok());
  EXPECT_EQ(gentlerStart(moving.value(), 0.9).status(), PlanStatus::kInvalidInput);
}

TEST(Trajectory, SlowedDownFollowsTheSamePathWithVelocitiesOverTheFactor) {
  const Trajectory t = makeTrajectory(wiggle());
  const double factor = 1.03;
  const auto slower = slowedDown(t, factor);
  ASSERT_TRUE(slower.ok());
  EXPECT_NEAR(slower.value().duration_s(), factor * t.duration_s(), 1e-12);
  for (int i = 0; i <= 20; ++i) {
    const TrajectorySample a = t.sample(t.duration_s() * i / 20.0);
    const TrajectorySample b = slower.value().sample(factor * a.t);
    EXPECT_NEAR((b.q - a.q).norm(), 0.0, 1e-9);
    EXPECT_NEAR((factor * b.qdot - a.qdot).norm(), 0.0, 1e-9);
  }
  EXPECT_EQ(slowedDown(t, 0.9).status(), PlanStatus::kInvalidInput);
  EXPECT_EQ(slowedDown(t, NAN).status(), PlanStatus::kInvalidInput);
}

TEST(Trajectory, SampleDoesNotAllocate) {
  const Trajectory t = makeTrajectory(wiggle());
  const long before = cyber::test::allocationCount();
  double sum = 0.0;
  for (int i = 0; i < 1000; ++i) sum += t.sample(t.duration_s() * i / 999.0).volts.sum();
  EXPECT_EQ(cyber::test::allocationCount(), before);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace cyber::planner

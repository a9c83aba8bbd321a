// The reachability estimate of a path's duration (path_timing.hpp) against the closed form of a
// bang-bang motion: on a straight line where only a constant acceleration limit binds, the
// fastest way from v0 to rest over a distance D speeds up at A and brakes at A, and the estimate
// is that time (never less: its profile is a motion within the limits) on a grid with a node at
// the switch, and approaches it on any grid. Its fractions and times, and its refusals.

#include "timing/path_timing.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include <gtest/gtest.h>

#include "path/joined_path.hpp"
#include "topp_fixtures.hpp"

namespace cyber::planner {
namespace {

constexpr double kAcceleration = 4.0;  // m/s^2
constexpr double kDistance = 1.0;      // m, along the elevator alone

// Drives whose voltage and current never bind along the elevator (no gains, a huge current
// limit): only the elevator's acceleration limit does.
DriveModel accelerationLimited() {
  DriveParams elevator = testing::elevatorDrive();
  elevator.kS_volts = elevator.kG_volts = elevator.kV = elevator.kA = 0.0;
  elevator.current_limit_amps = 1e9;
  elevator.acceleration_limit = kAcceleration;
  return testing::drivesOf(elevator, testing::armDrive());
}

const StraightPath kLine(JointVector{{0.5, 1.0}}, JointVector{{1.0, 0.0}}, kDistance);

// From v0 up at A to the peak, where braking at A just stops at D: v_p^2 = A D + v0^2 / 2.
double bangBangSeconds(double v0) {
  const double peak = std::sqrt(kAcceleration * kDistance + 0.5 * v0 * v0);
  return (2.0 * peak - v0) / kAcceleration;
}
// Where it switches from speeding up to braking.
double switchFraction(double v0) {
  const double peak = std::sqrt(kAcceleration * kDistance + 0.5 * v0 * v0);
  return (peak * peak - v0 * v0) / (2.0 * kAcceleration * kDistance);
}

TEST(PathTiming, IsTheBangBangTimeWithANodeAtTheSwitch) {
  const DriveModel drives = accelerationLimited();
  // Rest to rest switches halfway (a node of every odd grid); from 1 m/s at 7/16 of the way.
  ASSERT_DOUBLE_EQ(switchFraction(0.0), 0.5);
  ASSERT_DOUBLE_EQ(switchFraction(1.0), 7.0 / 16.0);
  for (const auto& [v0, points] : {std::pair{0.0, 101}, std::pair{0.0, 21}, std::pair{1.0, 161}, std::pair{1.0, 33}}) {
    const double closed = bangBangSeconds(v0);
    const double estimate = estimateDuration(kLine, drives, v0 * v0, points);
    EXPECT_GE(estimate, closed * (1.0 - 1e-12)) << "v0 " << v0 << ", " << points << " points";
    EXPECT_LE(estimate, closed * (1.0 + 1e-3)) << "v0 " << v0 << ", " << points << " points";
  }
  EXPECT_NEAR(bangBangSeconds(0.0), 2.0 * std::sqrt(kDistance / kAcceleration), 1e-15);
}

// Off a node the interval that holds the switch brakes early; the loss shrinks with the grid.
TEST(PathTiming, ApproachesTheBangBangTimeFromAboveOnAnyGrid) {
  const DriveModel drives = accelerationLimited();
  for (const double v0 : {0.0, 1.0, 2.0}) {
    const double closed = bangBangSeconds(v0);
    double previous_gap = std::numeric_limits<double>::infinity();
    for (const int points : {10, 40, 160}) {
      const double gap = estimateDuration(kLine, drives, v0 * v0, points) / closed - 1.0;
      EXPECT_GE(gap, -1e-12) << "v0 " << v0 << ", " << points << " points";
      EXPECT_LT(gap, 2.0 / points) << "v0 " << v0 << ", " << points << " points";
      EXPECT_LT(gap, previous_gap + 1e-4) << "v0 " << v0 << ", " << points << " points";
      previous_gap = gap;
    }
  }
}

// Each node's time is the bang-bang motion's at that fraction of the way.
TEST(PathTiming, FractionsAndTimesFollowTheMotion) {
  const DriveModel drives = accelerationLimited();
  const TimedFractions times = reachabilityTimes(kLine, drives, 0.0, 101);
  ASSERT_EQ(times.fraction.size(), 101u);
  ASSERT_EQ(times.time_s.size(), 101u);
  EXPECT_EQ(times.fraction.front(), 0.0);
  EXPECT_EQ(times.fraction.back(), 1.0);
  EXPECT_EQ(times.time_s.front(), 0.0);
  EXPECT_EQ(times.time_s.back(), estimateDuration(kLine, drives, 0.0, 101));
  const double total = bangBangSeconds(0.0);
  for (size_t i = 1; i < times.fraction.size(); ++i) {
    EXPECT_GT(times.fraction[i], times.fraction[i - 1]);
    EXPECT_GT(times.time_s[i], times.time_s[i - 1]);
    const double f = times.fraction[i];
    // Up at A to halfway, then the mirror image.
    const double expected = f <= 0.5 ? std::sqrt(2.0 * f * kDistance / kAcceleration)
                                     : total - std::sqrt(2.0 * (1.0 - f) * kDistance / kAcceleration);
    EXPECT_NEAR(times.time_s[i], expected, 2e-3 * total) << "fraction " << f;
  }
}

TEST(PathTiming, AZeroLengthPathTakesNoTime) {
  const StraightPath point(JointVector{{0.5, 1.0}}, JointVector{{1.0, 0.0}}, 0.0);
  const TimedFractions times = reachabilityTimes(point, accelerationLimited(), 0.0, 50);
  ASSERT_EQ(times.fraction.size(), 1u);
  EXPECT_EQ(times.fraction[0], 0.0);
  EXPECT_EQ(times.time_s[0], 0.0);
  EXPECT_EQ(estimateDuration(point, accelerationLimited(), 0.0, 50), 0.0);
}

// Faster than 2 A D cannot be stopped within D; a drive that cannot hold the joint at all gives
// no profile either: both are no estimate (infinity) and no times.
TEST(PathTiming, NoProfileIsNoEstimate) {
  const DriveModel drives = accelerationLimited();
  const double stoppable = 2.0 * kAcceleration * kDistance;
  EXPECT_TRUE(std::isfinite(estimateDuration(kLine, drives, 0.95 * stoppable, 101)));
  EXPECT_EQ(estimateDuration(kLine, drives, 1.05 * stoppable, 101), std::numeric_limits<double>::infinity());
  EXPECT_TRUE(reachabilityTimes(kLine, drives, 1.05 * stoppable, 101).time_s.empty());
  DriveParams weak = testing::elevatorDrive();
  weak.kG_volts = 13.0;  // gravity alone needs more than the 12 V limit
  const DriveModel cannot_hold = testing::drivesOf(weak, testing::armDrive());
  EXPECT_EQ(estimateDuration(kLine, cannot_hold, 0.0, 101), std::numeric_limits<double>::infinity());
  EXPECT_TRUE(reachabilityTimes(kLine, cannot_hold, 0.0, 101).fraction.empty());
}

}  // namespace
}  // namespace cyber::planner

// The sampled ride (trajectory.hpp) against what it must find: the planner's own time on a
// time-optimal path, a known slowdown of it, the same on uneven samples, and the effect of sampling
// at a moving start's turn (docs/performance.md, "Seeded random moves on the three robots").
#include "cyber/planner/trajectory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "cyber/planner/motion_planner.hpp"
#include "shipped_robots.hpp"

namespace cyber::planner {
namespace {

using test::namedPose;
using test::ShippedRobot;
using test::shippedRobot;

std::shared_ptr<const Trajectory> planned(const ShippedRobot& robot, const PlanRequest& request) {
  const auto plan = robot.planner.plan(request);
  EXPECT_TRUE(plan.ok()) << plan.error().message;
  return plan.value().trajectory;
}

PlanRequest namedMove(const ShippedRobot& robot, const char* from, const char* to) {
  PlanRequest request;
  request.start = namedPose(robot.config, "none", from);
  request.goal = namedPose(robot.config, "none", to);
  return request;
}

// Fine enough to resolve where the path's tangent goes to zero (shipped_robots.hpp).
using test::kRideStepS;

double ratio(const Trajectory& trajectory, double step_s) {
  const std::optional<double> ride = fastestRideAlongPath(trajectory, step_s);
  EXPECT_TRUE(ride.has_value());
  return trajectory.duration_s() / ride.value_or(1.0);
}

// The planner's time-optimal parameterisation of a path from rest is the fastest ride of that path,
// up to its grid and the 1 % its limit check allows between grid points (docs/algorithm.md
// section 3): on every robot, from a stowed pose and back to one. (On 1 ms samples the ride gains
// 2-5 % on these moves: arriving at rest, q' -> 0 as at a turn, below.)
TEST(SampledRide, FindsThePlannersOwnTimeOnAPathItTimedOptimally) {
  for (const auto& [name, from, to] :
       {std::tuple{"reefscape-2025", "STOW", "L4"}, std::tuple{"reefscape-2025", "L2", "STOW"},
        std::tuple{"chargedup-2023-double-jointed", "HOMED", "DOUBLE_SUBSTATION"},
        std::tuple{"pivot-telescope", "STOW", "REACH_UP"}}) {
    const ShippedRobot& robot = shippedRobot(name);
    const auto trajectory = planned(robot, namedMove(robot, from, to));
    ASSERT_TRUE(trajectory);
    EXPECT_NEAR(ratio(*trajectory, kRideStepS), 1.0, 0.01) << name << " " << from << " -> " << to;
  }
}

// A ride that cannot fail finds nothing: the same path 1.25 times slower is 1.25 times the ride.
TEST(SampledRide, FindsASlowdownOfThatPath) {
  const ShippedRobot& robot = shippedRobot("reefscape-2025");
  const auto trajectory = planned(robot, namedMove(robot, "STOW", "L4"));
  ASSERT_TRUE(trajectory);
  const auto slowed = slowedDown(*trajectory, 1.25);
  ASSERT_TRUE(slowed.ok());
  EXPECT_NEAR(ratio(slowed.value(), kRideStepS) / ratio(*trajectory, kRideStepS), 1.25, 0.005);
}

// The ride reads each interval's own length: on samples 10 us apart on average, each moved by up
// to 40 % of that at random, it finds what it finds on even ones.
TEST(SampledRide, FindsTheSameRideOnUnevenSamples) {
  const ShippedRobot& robot = shippedRobot("pivot-telescope");
  const auto trajectory = planned(robot, namedMove(robot, "STOW", "REACH_UP"));
  ASSERT_TRUE(trajectory);
  const double duration = trajectory->duration_s();
  const auto intervals = static_cast<size_t>(std::ceil(duration / kRideStepS));
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-0.4, 0.4);
  std::vector<double> times_s(intervals + 1);
  for (size_t k = 1; k < intervals; ++k)
    times_s[k] = duration * (static_cast<double>(k) + jitter(random)) / static_cast<double>(intervals);
  times_s.back() = duration;
  const std::optional<double> uneven = fastestRideAlongSamples(*trajectory, times_s);
  const std::optional<double> even = fastestRideAlongPath(*trajectory, kRideStepS);
  ASSERT_TRUE(uneven && even);
  EXPECT_NEAR(*uneven / *even, 1.0, 1e-3);
  EXPECT_FALSE(fastestRideAlongSamples(*trajectory, std::vector<double>{0.0}).has_value()) << "one sample is no ride";
}

// A plan that stops first and goes back: at the turn q' -> 0, and a ride on samples passes it
// between two of them faster than any motor could reverse. What it gains shrinks with the spacing
// (docs/performance.md: 1.17 at 1 ms, within 1.01 at 10 us).
TEST(SampledRide, GainsAtAMovingStartsTurnShrinkWithTheSpacing) {
  const ShippedRobot& robot = shippedRobot("reefscape-2025");
  PlanRequest request;
  request.start = JointVector{{0.708106406, 3.11534736}};
  request.start_velocity = JointVector{{-0.00719163449, 10.2194838}};
  request.goal = JointVector{{0.5622, 2.8539}};
  const auto trajectory = planned(robot, request);
  ASSERT_TRUE(trajectory);
  const double at_1ms = ratio(*trajectory, 1e-3);
  const double at_100us = ratio(*trajectory, 1e-4);
  const double at_10us = ratio(*trajectory, kRideStepS);
  EXPECT_GT(at_1ms, 1.1);
  EXPECT_GT(at_1ms, at_100us);
  EXPECT_GT(at_100us, at_10us);
  EXPECT_LE(at_10us, 1.02);
  RecordProperty("ratio_1ms", std::to_string(at_1ms));
  RecordProperty("ratio_100us", std::to_string(at_100us));
  RecordProperty("ratio_10us", std::to_string(at_10us));
}

}  // namespace
}  // namespace cyber::planner

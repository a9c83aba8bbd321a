// The defaults derived from the robot (cyber/config/derived_defaults.hpp; docs/configuration.md,
// "Defaults derived from the robot"): each rule on robots whose numbers are worked by hand.

#include "cyber/config/derived_defaults.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cyber/config/load_config.hpp"
#include "shipped_robots.hpp"

namespace cyber::config {
namespace {

using planner::JointType;

Config minimalRobot() { return loadConfigFile(test::sourceFile("tests/fixtures/minimal-robot.toml")); }
Config shipped(const std::string& name) { return loadConfigFile(test::sourceFile("config/" + name + ".toml")); }

// The minimal robot's lift (1 m per m) and its arm, whose tip is 0.5 m from its pivot.
TEST(DerivedDefaults, TheMinimalRobotsNumbersAreTheRulesOnes) {
  const DerivedPlannerDefaults d = derivePlannerDefaults(minimalRobot().robot);
  EXPECT_DOUBLE_EQ(d.sweep_m_per_unit[0], 1.0);
  EXPECT_DOUBLE_EQ(d.sweep_m_per_unit[1], 0.5);
  EXPECT_DOUBLE_EQ(d.metric[0], 1.0);
  EXPECT_DOUBLE_EQ(d.metric[1], 0.25);       // (0.5 / 1)^2
  EXPECT_DOUBLE_EQ(d.grid_step[0], 0.04);    // one clearance of lift travel
  EXPECT_DOUBLE_EQ(d.grid_step[1], 0.08);    // 0.08 rad moves the tip by one clearance
  EXPECT_DOUBLE_EQ(d.potential_range, 0.2);  // five clearances
}

// The reach counts the held pieces too: the algae's far edge is 0.6354 m from the arm's pivot.
TEST(DerivedDefaults, AReachIsTheFarthestPointOfTheLinksAndPiecesCarried) {
  const planner::RobotModel reef = shipped("reefscape-2025").robot;
  EXPECT_DOUBLE_EQ(reach_m(reef, 1), 0.6354);
  const DerivedPlannerDefaults d = derivePlannerDefaults(reef);
  EXPECT_DOUBLE_EQ(d.metric[0], 1.0);
  EXPECT_NEAR(d.metric[1], 0.6354 * 0.6354, 1e-15);
  EXPECT_DOUBLE_EQ(d.grid_step[0], 0.03);
  EXPECT_NEAR(d.grid_step[1], 0.03 / 0.6354, 1e-15);
  EXPECT_EQ(d.potential_range, 0.15);  // bit for bit: the key the shipped file no longer has
}

// A first revolute joint carries the second joint's links over the second joint's whole range: the
// double-jointed arm's elbow cannot straighten (0.5236 rad at least), so its cone's tip is farthest
// at that bend (its lower corner, which the bend turns outward); the telescope's ball is farthest at
// full extension.
TEST(DerivedDefaults, AFirstJointsReachTakesTheSecondJointsRangeIntoAccount) {
  const planner::RobotModel arm = shipped("chargedup-2023-double-jointed").robot;
  const planner::Point2 tip(1.205, -0.015);
  const double bend = 0.5235987756;
  const planner::Point2 at_bend =
      planner::Point2(0.686, 0.0) + planner::Point2(std::cos(bend) * tip.x() - std::sin(bend) * tip.y(),
                                                    std::sin(bend) * tip.x() + std::cos(bend) * tip.y());
  // (Its upper corner at the range's other end, 2e-11 rad short of the mirror image, is as far.)
  EXPECT_NEAR(reach_m(arm, 0), at_bend.norm(), 1e-9);
  EXPECT_NEAR(reach_m(arm, 1), tip.norm(), 1e-15);

  const planner::RobotModel pivot = shipped("pivot-telescope").robot;
  EXPECT_NEAR(reach_m(pivot, 0), std::hypot(0.7909 + 0.9, 0.0459), 1e-15);
  const DerivedPlannerDefaults d = derivePlannerDefaults(pivot);
  EXPECT_DOUBLE_EQ(d.metric[0], 1.0);
  EXPECT_NEAR(d.metric[1], 1.0 / std::pow(std::hypot(1.6909, 0.0459), 2), 1e-12);
}

// A second revolute joint that can line a point up with its own origin puts it at the sum of the
// two distances; one kept from it by its range reaches less.
TEST(DerivedDefaults, TheSecondJointsAlignedAngleCountsOnlyWithinItsRange) {
  planner::RobotModel robot = minimalRobot().robot;
  robot.joints[0] = {"shoulder", JointType::kRevolute, planner::Point2::Zero(), 0.0, {0.0, 1.0}};
  robot.joints[1] = {"elbow", JointType::kRevolute, planner::Point2(1.0, 0.0), 0.0, {-1.0, 1.0}};
  EXPECT_NEAR(reach_m(robot, 0), 1.5, 1e-12);  // the arm's tip (0.5, 0) straight out at q1 = 0
  robot.joints[1].range = {1.0, 2.0};
  EXPECT_NEAR(reach_m(robot, 0), std::hypot(1.0 + 0.5 * std::cos(1.0), 0.5 * std::sin(1.0)), 1e-12);
}

TEST(DerivedDefaults, TheGridKeepsBetweenItsLeastAndMostCells) {
  planner::RobotModel robot = minimalRobot().robot;
  robot.clearance_m = 0.0;  // one clearance would be a step of 0
  DerivedPlannerDefaults d = derivePlannerDefaults(robot);
  EXPECT_DOUBLE_EQ(d.grid_step[0], 1.2 / kGridMaxCells);
  EXPECT_DOUBLE_EQ(d.grid_step[1], 3.14 / kGridMaxCells);
  EXPECT_DOUBLE_EQ(d.potential_range, kMinPotentialRange_m);
  robot.clearance_m = 0.2;  // 6 cells of lift, 4 of arm
  d = derivePlannerDefaults(robot);
  EXPECT_DOUBLE_EQ(d.grid_step[0], 1.2 / kGridMinCells);
  EXPECT_DOUBLE_EQ(d.grid_step[1], 3.14 / kGridMinCells);
}

// A revolute joint that carries nothing still weighs something and has a finite step.
TEST(DerivedDefaults, AJointCarryingNothingCountsAsTheLeastReach) {
  planner::RobotModel robot = minimalRobot().robot;
  robot.links[0].joint = 0;
  EXPECT_DOUBLE_EQ(reach_m(robot, 1), kMinReach_m);
  const DerivedPlannerDefaults d = derivePlannerDefaults(robot);
  EXPECT_GT(d.metric[1], 0.0);
  EXPECT_DOUBLE_EQ(d.grid_step[1], 3.14 / kGridMinCells);
}

}  // namespace
}  // namespace cyber::config

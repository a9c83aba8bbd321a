#include "cyber/daemon/goal_request.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "reference_model.hpp"

namespace cyber::daemon {
namespace {

using planner::PlanStatus;

GoalRequest goalAt(double elevator_m, double arm_rad, std::string scene = {}) {
  return GoalRequest{7, elevator_m, arm_rad, false, false, std::move(scene)};
}

TEST(ValidateGoal, AcceptsAGoalInsideTheLimits) {
  const auto& robot = cyber::test::referenceModel();
  GoalRequest goal = goalAt(1.0, 1.5);
  goal.held_coral = true;
  auto valid = validateGoal(goal, robot);
  ASSERT_TRUE(valid) << valid.error().reason;
  EXPECT_EQ(valid.value().request_id, 7);
  EXPECT_EQ(valid.value().q, planner::JointVector(1.0, 1.5));
  EXPECT_TRUE(valid.value().pieces.coral);
  EXPECT_FALSE(valid.value().pieces.algae);
  EXPECT_EQ(valid.value().scene, 0);
}

TEST(ValidateGoal, RejectsNonFiniteValuesNamingTheField) {
  const auto& robot = cyber::test::referenceModel();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const auto& [goal, field] : {std::pair{goalAt(nan, 1.0), "elevator_m"}, std::pair{goalAt(0.5, inf), "arm_rad"},
                                    std::pair{goalAt(-inf, 1.0), "elevator_m"}}) {
    auto result = validateGoal(goal, robot);
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error().status, PlanStatus::kInvalidInput);
    EXPECT_NE(result.error().reason.find(field), std::string::npos) << result.error().reason;
  }
}

TEST(ValidateGoal, RejectsOutOfRangeJointsWithTheLimits) {
  const auto& robot = cyber::test::referenceModel();
  auto high = validateGoal(goalAt(2.5, 1.0), robot);
  ASSERT_FALSE(high);
  EXPECT_EQ(high.error().status, PlanStatus::kGoalOutOfRange);
  EXPECT_NE(high.error().reason.find("elevator_m = 2.5 m is outside [0, 2] m"), std::string::npos)
      << high.error().reason;
  auto negative = validateGoal(goalAt(0.5, -0.1), robot);
  ASSERT_FALSE(negative);
  EXPECT_EQ(negative.error().status, PlanStatus::kGoalOutOfRange);
  EXPECT_NE(negative.error().reason.find("arm_rad"), std::string::npos);
  // The limits themselves are inside.
  EXPECT_TRUE(validateGoal(goalAt(robot.elevator_range_m.max, robot.arm_range_rad.min), robot));
}

TEST(ValidateGoal, ResolvesSceneNamesAndRejectsUnknownOnes) {
  const auto& robot = cyber::test::referenceModel();
  auto open = validateGoal(goalAt(0.5, 1.0, "open"), robot);
  ASSERT_TRUE(open);
  EXPECT_EQ(open.value().scene, robot.sceneIndex("open"));
  EXPECT_GT(open.value().scene, 0);
  auto unknown = validateGoal(goalAt(0.5, 1.0, "moon"), robot);
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.error().status, PlanStatus::kInvalidInput);
  EXPECT_NE(unknown.error().reason.find("unknown scene 'moon' (known: reef, open)"), std::string::npos)
      << unknown.error().reason;
}

}  // namespace
}  // namespace cyber::daemon

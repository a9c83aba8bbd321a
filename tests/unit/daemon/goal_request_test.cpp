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
  EXPECT_EQ(valid.value().pieces, cyber::test::referencePieces("coral"));
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
  EXPECT_TRUE(validateGoal(goalAt(robot.range(0).max, robot.range(1).min), robot));
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

// The reproducer of tests/fuzz/regressions/lcm_decode: a scene name with a NUL byte was echoed in
// the rejection reason, which LCM sends with the uninitialised rest of its buffer.
TEST(ValidateGoal, RefusesSceneNamesThatAreNotShortPrintableWordsWithoutEchoingThem) {
  const auto& robot = cyber::test::referenceModel();
  for (const std::string& name : {std::string("reef\0oon", 8), std::string("reef\n"), std::string(65, 'a'),
                                  std::string("r\xc3\xa9"
                                              "ef")}) {
    auto refused = validateGoal(goalAt(0.5, 1.0, name), robot);
    ASSERT_FALSE(refused) << name;
    EXPECT_EQ(refused.error().status, PlanStatus::kInvalidInput);
    EXPECT_NE(refused.error().reason.find("scene_name is not a name"), std::string::npos) << refused.error().reason;
    EXPECT_EQ(refused.error().reason.find(name), std::string::npos) << "echoed: " << refused.error().reason;
    EXPECT_EQ(refused.error().reason.find('\0'), std::string::npos);
  }
  // 64 printable characters are a name (an unknown one).
  const auto long_name = validateGoal(goalAt(0.5, 1.0, std::string(64, 'a')), robot);
  ASSERT_FALSE(long_name);
  EXPECT_NE(long_name.error().reason.find("unknown scene"), std::string::npos) << long_name.error().reason;
}

}  // namespace
}  // namespace cyber::daemon

#include "cyber/daemon/goal_request.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "reference_model.hpp"

namespace cyber::daemon {
namespace {

using planner::PlanStatus;

// The reference robot: joint 0 "elevator" (m, [0, 2]), joint 1 "arm" (rad); pieces algae and
// coral (in the config's order); scenes reef (offset range [0, 0.3] m) and open (no offsets).
GoalRequest goalAt(double q0, double q1, std::string scene = {}) {
  GoalRequest goal;
  goal.request_id = 7;
  goal.position = {q0, q1};
  goal.scene_name = std::move(scene);
  return goal;
}

GoalRequest holding(std::vector<std::string> pieces) {
  GoalRequest goal = goalAt(1.0, 1.5);
  goal.num_pieces = static_cast<int>(pieces.size());
  goal.pieces = std::move(pieces);
  return goal;
}

// The reason of a refused goal, after checking its status.
std::string refused(const GoalRequest& goal, PlanStatus status = PlanStatus::kInvalidInput) {
  auto result = validateGoal(goal, cyber::test::referenceModel());
  EXPECT_FALSE(result);
  if (result) return "";
  EXPECT_EQ(result.error().status, status) << result.error().message;
  return result.error().message;
}

TEST(ValidateGoal, AcceptsAGoalInsideTheLimits) {
  const auto& robot = cyber::test::referenceModel();
  auto valid = validateGoal(holding({"coral"}), robot);
  ASSERT_TRUE(valid) << valid.error().message;
  EXPECT_EQ(valid.value().request_id, 7);
  EXPECT_EQ(valid.value().q, (planner::JointVector{{1.0, 1.5}}));
  EXPECT_EQ(valid.value().pieces, cyber::test::referencePieces("coral"));
  EXPECT_EQ(valid.value().scene, 0);
  EXPECT_EQ(valid.value().scene_offset_m, 0.0);
}

// The message's num_joints must be the robot's: a goal of another robot's joints is not guessed at.
TEST(ValidateGoal, RejectsAJointCountOtherThanTheRobotsNamingTheJoints) {
  for (const std::vector<double>& values :
       {std::vector<double>{}, std::vector<double>{1.0}, std::vector<double>{1.0, 1.5, 0.0}}) {
    GoalRequest goal = goalAt(1.0, 1.5);
    goal.position = values;
    const std::string reason = refused(goal);
    EXPECT_EQ(reason, fmt::format("num_joints = {} but this robot has 2 joints (elevator, arm)", values.size()));
  }
}

// A stand-in for the daemon's configuration (daemon/io/named_poses.hpp): "L3" of the held set
// "none" only, and the names it knows in its refusal.
planner::Result<planner::JointVector> fakePoses(planner::HeldPieces held, const std::string& name) {
  if (held == planner::HeldPieces{} && name == "L3") return planner::JointVector{{1.22, 5.69}};
  if (name == "HIGH") return planner::JointVector{{2.5, 1.0}};  // past the elevator's 2 m
  return planner::Result<planner::JointVector>::failure(PlanStatus::kInvalidInput,
                                                        fmt::format("no pose \"{}\" (its poses: L3)", name));
}

TEST(ValidateGoal, ANamedGoalTakesThePoseOfItsHeldSetAndIgnoresThePosition) {
  const auto& robot = cyber::test::referenceModel();
  GoalRequest goal = goalAt(0.0, 0.0);
  goal.position.clear();  // num_joints = 0: a named goal needs no values
  goal.pose_name = "L3";
  auto valid = validateGoal(goal, robot, fakePoses);
  ASSERT_TRUE(valid) << valid.error().message;
  EXPECT_EQ(valid.value().q, (planner::JointVector{{1.22, 5.69}}));
  goal.position = {9.0, 9.0, 9.0};
  auto ignored = validateGoal(goal, robot, fakePoses);
  ASSERT_TRUE(ignored) << ignored.error().message;
  EXPECT_EQ(ignored.value().q, (planner::JointVector{{1.22, 5.69}}));
}

TEST(ValidateGoal, RejectsAnUnknownNameWithTheLookupsReasonAndChecksANamedPoseLikeValues) {
  const auto& robot = cyber::test::referenceModel();
  GoalRequest goal = holding({"coral"});
  goal.pose_name = "L3";  // fakePoses has it only for "none"
  auto other_set = validateGoal(goal, robot, fakePoses);
  ASSERT_FALSE(other_set);
  EXPECT_EQ(other_set.error().message, "no pose \"L3\" (its poses: L3)");
  goal = goalAt(0.0, 0.0);
  goal.pose_name = "HIGH";
  auto high = validateGoal(goal, robot, fakePoses);
  ASSERT_FALSE(high);
  EXPECT_EQ(high.error().status, PlanStatus::kGoalOutOfRange);
  goal.pose_name = "L3";
  EXPECT_NE(refused(goal).find("no pose \"L3\": this daemon has no named poses"), std::string::npos)
      << "without a lookup no name resolves";
  goal.pose_name = std::string("L\0", 2);
  EXPECT_EQ(validateGoal(goal, robot, fakePoses).error().message.find('\0'), std::string::npos);
}

TEST(ValidateGoal, PiecesComeByTheConfigsNamesInAnyOrder) {
  const auto& robot = cyber::test::referenceModel();
  auto both = validateGoal(holding({"algae", "coral"}), robot);
  ASSERT_TRUE(both) << both.error().message;
  EXPECT_EQ(both.value().pieces, cyber::test::referencePieces("coral+algae"));
  auto none = validateGoal(holding({}), robot);
  ASSERT_TRUE(none) << none.error().message;
  EXPECT_EQ(none.value().pieces, cyber::test::referencePieces("none"));
}

TEST(ValidateGoal, RejectsNonFiniteValuesNamingTheJoint) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const auto& [goal, field] : {std::pair{goalAt(nan, 1.0), "position[0] (elevator) is not finite (nan)"},
                                    std::pair{goalAt(0.5, inf), "position[1] (arm) is not finite (inf)"},
                                    std::pair{goalAt(-inf, 1.0), "position[0] (elevator) is not finite (-inf)"}}) {
    EXPECT_NE(refused(goal).find(field), std::string::npos) << refused(goal);
  }
}

TEST(ValidateGoal, RejectsOutOfRangeJointsWithTheLimitsInTheJointsUnit) {
  const auto& robot = cyber::test::referenceModel();
  const std::string high = refused(goalAt(2.5, 1.0), PlanStatus::kGoalOutOfRange);
  EXPECT_NE(high.find("position[0] (elevator) = 2.5 m is outside [0, 2] m"), std::string::npos) << high;
  const std::string negative = refused(goalAt(0.5, -0.1), PlanStatus::kGoalOutOfRange);
  EXPECT_NE(negative.find("position[1] (arm) = -0.1 rad is outside"), std::string::npos) << negative;
  // The limits themselves are inside.
  EXPECT_TRUE(validateGoal(goalAt(robot.range(0).max, robot.range(1).min), robot));
}

TEST(ValidateGoal, RejectsAnUnknownPieceListingTheConfigsPieces) {
  const std::string reason = refused(holding({"coral", "cone"}));
  EXPECT_NE(reason.find("unknown game piece 'cone' in pieces[1] (this robot's: algae, coral)"), std::string::npos)
      << reason;
  // The old message's words are not names: "none" is not a piece either.
  EXPECT_NE(refused(holding({"none"})).find("unknown game piece 'none'"), std::string::npos);
}

TEST(ValidateGoal, RejectsAPieceNamedTwice) {
  const std::string reason = refused(holding({"coral", "algae", "coral"}));
  EXPECT_NE(reason.find("game piece 'coral' is named twice"), std::string::npos) << reason;
}

TEST(ValidateGoal, RejectsTooManyPiecesOrACountThatDoesNotMatchTheNames) {
  const std::string many = refused(holding({"coral", "algae", "a", "b", "c"}));
  EXPECT_NE(many.find("num_pieces = 5 is outside 0..4"), std::string::npos) << many;
  GoalRequest negative = holding({});
  negative.num_pieces = -1;
  EXPECT_NE(refused(negative).find("num_pieces = -1 is outside 0..4"), std::string::npos);
  GoalRequest mismatch = holding({"coral"});
  mismatch.num_pieces = 2;
  EXPECT_NE(refused(mismatch).find("num_pieces = 2 but 1 piece names came"), std::string::npos);
}

TEST(ValidateGoal, RefusesPieceNamesThatAreNotPrintableWordsWithoutEchoingThem) {
  const std::string name("cor\0al", 6);
  const std::string reason = refused(holding({name}));
  EXPECT_NE(reason.find("pieces[0] is not a name"), std::string::npos) << reason;
  EXPECT_EQ(reason.find('\0'), std::string::npos);
}

TEST(ValidateGoal, ResolvesSceneNamesAndRejectsUnknownOnes) {
  const auto& robot = cyber::test::referenceModel();
  auto open = validateGoal(goalAt(0.5, 1.0, "open"), robot);
  ASSERT_TRUE(open);
  EXPECT_EQ(open.value().scene, robot.sceneIndex("open"));
  EXPECT_GT(open.value().scene, 0);
  const std::string unknown = refused(goalAt(0.5, 1.0, "moon"));
  EXPECT_NE(unknown.find("unknown scene 'moon' (known: reef, open)"), std::string::npos) << unknown;
}

TEST(ValidateGoal, TakesASceneOffsetWithinTheScenesRange) {
  const auto& robot = cyber::test::referenceModel();
  GoalRequest goal = goalAt(0.5, 1.0, "reef");
  goal.scene_offset_m = 0.3;
  auto valid = validateGoal(goal, robot);
  ASSERT_TRUE(valid) << valid.error().message;
  EXPECT_EQ(valid.value().scene_offset_m, 0.3);
  goal.scene_offset_m = 0.0;
  EXPECT_TRUE(validateGoal(goal, robot));
}

TEST(ValidateGoal, RejectsASceneOffsetOutsideTheScenesRangeOrNotFinite) {
  GoalRequest far = goalAt(0.5, 1.0);  // the default scene, reef
  far.scene_offset_m = 0.31;
  const std::string reason = refused(far);
  EXPECT_NE(reason.find("scene_offset_m = 0.31 m is outside scene reef's offset range [0, 0.3] m"), std::string::npos)
      << reason;
  GoalRequest behind = goalAt(0.5, 1.0, "reef");
  behind.scene_offset_m = -0.05;
  EXPECT_NE(refused(behind).find("outside scene reef's offset range"), std::string::npos);
  // A scene that does not move takes only 0.
  GoalRequest open = goalAt(0.5, 1.0, "open");
  open.scene_offset_m = 0.1;
  EXPECT_NE(refused(open).find("outside scene open's offset range [0, 0] m"), std::string::npos) << refused(open);
  GoalRequest nan = goalAt(0.5, 1.0, "reef");
  nan.scene_offset_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(refused(nan).find("scene_offset_m is not finite (nan)"), std::string::npos) << refused(nan);
}

// The reproducer of tests/fuzz/regressions/lcm_decode: a scene name with a NUL byte was echoed in
// the rejection reason, which LCM sends with the uninitialised rest of its buffer.
TEST(ValidateGoal, RefusesSceneNamesThatAreNotShortPrintableWordsWithoutEchoingThem) {
  const auto& robot = cyber::test::referenceModel();
  for (const std::string& name : {std::string("reef\0oon", 8), std::string("reef\n"), std::string(65, 'a'),
                                  std::string("r\xc3\xa9"
                                              "ef")}) {
    const std::string reason = refused(goalAt(0.5, 1.0, name));
    EXPECT_NE(reason.find("scene_name is not a name"), std::string::npos) << reason;
    EXPECT_EQ(reason.find(name), std::string::npos) << "echoed: " << reason;
    EXPECT_EQ(reason.find('\0'), std::string::npos);
  }
  // 64 printable characters are a name (an unknown one).
  const auto long_name = validateGoal(goalAt(0.5, 1.0, std::string(64, 'a')), robot);
  ASSERT_FALSE(long_name);
  EXPECT_NE(long_name.error().message.find("unknown scene"), std::string::npos) << long_name.error().message;
}

}  // namespace
}  // namespace cyber::daemon

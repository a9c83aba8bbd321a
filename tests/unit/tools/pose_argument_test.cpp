// A pose on the command line (tools/cyber-plan/pose_argument.cpp): numbers or a name, and the
// name looked up among the poses the configuration gives the held pieces (config/reefscape-2025.toml).

#include "pose_argument.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cyber::tools {
namespace {

PoseArgument parsed(std::string_view text, cli::NonFinite non_finite = cli::NonFinite::kReject) {
  const auto pose = parsePoseArgument(text, non_finite);
  EXPECT_TRUE(pose.ok()) << text << ": " << (pose.ok() ? "" : pose.error().message);
  return pose.ok() ? pose.value() : PoseArgument{};
}

std::string refused(std::string_view text, cli::NonFinite non_finite = cli::NonFinite::kReject) {
  const auto pose = parsePoseArgument(text, non_finite);
  EXPECT_EQ(pose.status(), cli::ArgumentStatus::kBadUsage) << text;
  return pose.ok() ? "" : pose.error().message;
}

TEST(PoseArgument, NumbersSeparatedByCommasAreValues) {
  EXPECT_EQ(parsed("0.2,1.57").values, (std::vector<double>{0.2, 1.57}));
  EXPECT_TRUE(parsed("0.2,1.57").name.empty());
  EXPECT_EQ(parsed("-1,2,3e-1").values, (std::vector<double>{-1, 2, 0.3})) << "as many as given; the robot counts";
  EXPECT_EQ(parsed("1.5").values, std::vector<double>{1.5}) << "a number alone is a pose of one value";
}

TEST(PoseArgument, TextThatIsNotANumberIsAName) {
  for (const char* name : {"STOW", "L3", "ALGAE_LOW", "high-net", "3rd"}) {
    const PoseArgument pose = parsed(name);
    EXPECT_EQ(pose.name, name);
    EXPECT_TRUE(pose.values.empty()) << name;
  }
}

TEST(PoseArgument, ANumberListThatDoesNotParseIsRefused) {
  for (const char* bad : {"STOW,1", "1,", ",2", "1,,2", "1,2x", "nan,1", "1,inf", "nan", "-inf"}) {
    EXPECT_EQ(refused(bad), std::string("expects the joints' values in chain order separated by ',' (finite numbers) "
                                        "or a pose name, got '") +
                                bad + "'");
  }
  // cyber-goal sends non-finite values on for the daemon to refuse.
  const PoseArgument nan = parsed("nan,1", cli::NonFinite::kAccept);
  ASSERT_EQ(nan.values.size(), 2u);
  EXPECT_TRUE(std::isnan(nan.values[0]));
  EXPECT_TRUE(parsed("inf", cli::NonFinite::kAccept).name.empty()) << "a non-finite number is not a name";
  EXPECT_EQ(refused("1,x", cli::NonFinite::kAccept),
            "expects the joints' values in chain order separated by ',' (numbers) or a pose name, got '1,x'");
}

class ResolvePose : public ::testing::Test {
 protected:
  Result<planner::JointVector, cli::ArgumentStatus> resolve(std::string_view text, std::string_view pieces) const {
    const auto held = config_.robot.piecesNamed(pieces);
    EXPECT_TRUE(held.ok()) << pieces;
    return resolvePose(parsed(text), config_, held.value());
  }
  planner::JointVector q(std::string_view text, std::string_view pieces) const {
    const auto pose = resolve(text, pieces);
    EXPECT_TRUE(pose.ok()) << text << ": " << (pose.ok() ? "" : pose.error().message);
    return pose.ok() ? pose.value() : planner::JointVector::Constant(2, NAN);
  }
  std::string error(std::string_view text, std::string_view pieces) const {
    const auto pose = resolve(text, pieces);
    EXPECT_EQ(pose.status(), cli::ArgumentStatus::kBadUsage) << text;
    return pose.ok() ? "" : pose.error().message;
  }
  const config::Config config_ = config::loadEmbeddedDefaultConfig();
};

// [poses.none] L3 = [1.22, 5.69], [poses.coral] L3 = [1.27, 5.79]: the held pieces choose the table.
TEST_F(ResolvePose, ANameIsThePoseOfTheHeldSet) {
  EXPECT_EQ(q("STOW", "coral"), (planner::JointVector{{0.20, 1.57}}));
  EXPECT_EQ(q("L3", "coral"), (planner::JointVector{{1.27, 5.79}}));
  EXPECT_EQ(q("L3", "none"), (planner::JointVector{{1.22, 5.69}}));
  EXPECT_EQ(q("L3", ""), (planner::JointVector{{1.22, 5.69}}));
  EXPECT_EQ(q("HOLD_HIGH", "algae"), (planner::JointVector{{1.98, 5.69}}));
}

TEST_F(ResolvePose, NumbersAreThePoseWhenThereIsOnePerJoint) {
  EXPECT_EQ(q("0.5,-1", "coral"), (planner::JointVector{{0.5, -1.0}})) << "ranges are the planner's to judge";
  EXPECT_EQ(error("1,2,3", "none"), "expects 2 values, one per joint (elevator, arm), got 3");
  EXPECT_EQ(error("1.5", "none"), "expects 2 values, one per joint (elevator, arm), got 1");
}

TEST_F(ResolvePose, ANameTheHeldSetDoesNotDeclareListsTheNamesItDoes) {
  EXPECT_EQ(error("L5", "coral"),
            "no pose \"L5\" for the held set \"coral\" (its poses: STOW, INTAKE, L1, L2, L3, L4, NET)");
  EXPECT_EQ(error("stow", "algae"),
            "no pose \"stow\" for the held set \"algae\" (its poses: STOW, INTAKE, NET, HOLD_HIGH)")
      << "names are exact";
}

TEST_F(ResolvePose, ANameOfAnotherHeldSetSaysWhichSetsHaveIt) {
  EXPECT_EQ(error("HOLD_HIGH", "coral"),
            "no pose \"HOLD_HIGH\" for the held set \"coral\" (its poses: STOW, INTAKE, L1, L2, L3, L4, NET); it is a "
            "pose of \"algae\"");
  EXPECT_EQ(error("ALGAE_LOW", "algae"),
            "no pose \"ALGAE_LOW\" for the held set \"algae\" (its poses: STOW, INTAKE, NET, HOLD_HIGH); it is a pose "
            "of \"none\"");
}

TEST_F(ResolvePose, AHeldSetWithoutPosesSaysSo) {
  EXPECT_EQ(error("STOW", "coral,algae"),
            "no pose \"STOW\": the configuration names no poses for the held set \"algae+coral\"; it is a pose of "
            "\"none\", \"coral\", \"algae\"");
  EXPECT_EQ(error("UP", "algae+coral"),
            "no pose \"UP\": the configuration names no poses for the held set \"algae+coral\"");
}

}  // namespace
}  // namespace cyber::tools

// cyber-robot check (tools/cyber-robot/robot_check.hpp): the shipped robots pass with their known
// warnings, and a pose that collides in the default scene or a drive too weak for its load is an
// error that names it.

#include "robot_check.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <optional>
#include <sstream>

#include "robot_report.hpp"
#include "shipped_robots.hpp"

namespace cyber::tools {
namespace {

std::string fileText(const std::string& relative) {
  std::ifstream in(test::sourceFile(relative));
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The shipped pivot-telescope with `from` replaced by `to` (which must be there).
config::Config pivotTelescopeWith(const std::string& from, const std::string& to) {
  std::string text = fileText("config/pivot-telescope.toml");
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return config::parseConfig(text, "pivot-telescope (edited)");
}

// The severity of the one entry of pose `pose` of [poses.none] in `scene`.
std::optional<Severity> severityOf(const std::vector<PoseClearance>& poses, const std::string& pose,
                                   const std::string& scene) {
  std::optional<Severity> found;
  for (const PoseClearance& p : poses) {
    if (p.pose_set != "none" || p.pose != pose || p.scene != scene) continue;
    EXPECT_FALSE(found.has_value()) << pose << " twice in " << scene;
    found = p.severity;
  }
  return found;
}

RobotCheck fullCheck(const config::Config& config) {
  RobotCheck check;
  check.poses = checkPoseClearances(config);
  const auto planner = planner::MotionPlanner::create(config.robot, planner::GridSelection{0, 0.0});
  EXPECT_TRUE(planner.ok());
  if (planner) check.reach = checkReach(config, planner.value());
  const planner::HeldPieces heaviest = heaviestPieces(config.robot);
  check.heaviest_set = config.robot.pieceSetName(heaviest);
  check.drives = checkDrives(config.robot, heaviest);
  return check;
}

TEST(RobotCheck, EveryShippedRobotHasNoError) {
  for (const char* name : test::kShippedRobotNames) {
    const config::Config& config = test::shippedRobot(name).config;
    const RobotCheck check = fullCheck(config);
    EXPECT_EQ(check.count(Severity::kError), 0) << name << "\n" << robotReportText(config, check);
    size_t poses = 0;
    for (const config::PoseSet& set : config.poses) poses += set.poses.size();
    EXPECT_EQ(check.poses.size(), poses * config.robot.scenes.size()) << name;
    EXPECT_EQ(check.drives.size(), static_cast<size_t>(planner::kJointCount)) << name;
  }
}

// The reference robot's coral L4 is proven unreachable by flood fill (tests/unit/planner): its
// pairs are refused and it stands in a group of its own.
TEST(RobotCheck, TheReferenceRobotsUnreachablePoseStandsAlone) {
  const config::Config& config = test::shippedRobot("reefscape-2025").config;
  const RobotCheck check = fullCheck(config);
  const auto coral =
      std::find_if(check.reach.begin(), check.reach.end(), [](const PoseSetReach& r) { return r.pose_set == "coral"; });
  ASSERT_NE(coral, check.reach.end());
  ASSERT_EQ(coral->groups.size(), 2U);
  EXPECT_EQ(coral->groups[1], std::vector<std::string>{"L4"});
  EXPECT_EQ(coral->pairs_planned + static_cast<int>(coral->refused.size()), coral->poses * (coral->poses - 1));
  for (const RefusedPair& refused : coral->refused) EXPECT_TRUE(refused.from == "L4" || refused.to == "L4");
}

TEST(RobotCheck, APoseInsideAFieldElementOfTheDefaultSceneIsAnErrorNamingIt) {
  const config::Config config = pivotTelescopeWith("[poses.none]\n", "[poses.none]\nINTO_STEP = [0.0, 0.9]\n");
  const RobotCheck check = fullCheck(config);
  EXPECT_GE(check.count(Severity::kError), 1);
  const std::string text = robotReportText(config, check);
  EXPECT_NE(text.find("error: pose [poses.none] INTO_STEP"), std::string::npos) << text;
  EXPECT_NE(text.find("high_step"), std::string::npos) << text;
  EXPECT_EQ(severityOf(check.poses, "INTO_STEP", "open_field"), Severity::kOk);
}

// The same pose colliding only in a scene that is not the default is a warning.
TEST(RobotCheck, ACollisionInAnotherSceneIsAWarning) {
  config::Config config = pivotTelescopeWith("[poses.none]\n", "[poses.none]\nINTO_STEP = [0.0, 0.9]\n");
  std::swap(config.robot.scenes[0], config.robot.scenes[1]);
  EXPECT_EQ(severityOf(checkPoseClearances(config), "INTO_STEP", "steps"), Severity::kWarning);
}

TEST(RobotCheck, ADriveThatCannotHoldItsLoadIsAnErrorNamingIt) {
  const config::Config config = pivotTelescopeWith("current_limit_amps = 60.0", "current_limit_amps = 2.0");
  const std::vector<DriveCheck> drives = checkDrives(config.robot, heaviestPieces(config.robot));
  ASSERT_EQ(drives.size(), 2U);
  EXPECT_EQ(drives[0].joint, "pivot");
  EXPECT_EQ(drives[0].severity, Severity::kError);
  EXPECT_EQ(drives[1].severity, Severity::kOk);
  EXPECT_LT(drives[0].worst_acceleration, 0.0);
}

// A current limit just above what holding needs still moves both ways, slowly: the check is the
// boundary, not a margin.
TEST(RobotCheck, TheDriveCheckBoundaryIsTheHoldingCurrent) {
  const config::Config& shipped = test::shippedRobot("pivot-telescope").config;
  const std::vector<DriveCheck> drives = checkDrives(shipped.robot, heaviestPieces(shipped.robot));
  const double hold_amps = drives[0].hold_amps;
  config::Config config = shipped;
  config.robot.drives[0].current_limit_amps = hold_amps * 1.05;
  EXPECT_EQ(checkDrives(config.robot, heaviestPieces(config.robot))[0].severity, Severity::kOk);
  config.robot.drives[0].current_limit_amps = hold_amps * 0.95;
  EXPECT_EQ(checkDrives(config.robot, heaviestPieces(config.robot))[0].severity, Severity::kError);
}

TEST(RobotCheck, TheHeaviestSetHoldsEveryPieceWithMass) {
  const config::Config& config = test::shippedRobot("chargedup-2023-double-jointed").config;
  EXPECT_EQ(config.robot.pieceSetName(heaviestPieces(config.robot)), "cone+cube");
}

}  // namespace
}  // namespace cyber::tools

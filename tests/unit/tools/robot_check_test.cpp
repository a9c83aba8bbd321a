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

// config/NAME.toml with `from` replaced by `to` (which must be there).
config::Config robotWith(const std::string& name, const std::string& from, const std::string& to) {
  std::string text = fileText("config/" + name + ".toml");
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return config::parseConfig(text, name + " (edited)");
}

config::Config pivotTelescopeWith(const std::string& from, const std::string& to) {
  return robotWith("pivot-telescope", from, to);
}

// The one-joint and the three-joint robot of issue 34, not (yet) among the shipped ones.
config::Config robotNamed(const std::string& name) {
  return config::loadConfigFile(test::sourceFile("config/" + name + ".toml"));
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
    EXPECT_EQ(check.drives.size(), static_cast<size_t>(config.robot.jointCount())) << name;
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

// The one-joint intake and the elevator-pivot-wrist: every pose clear in its default scene and
// every drive able to hold and move its load, one drive per joint in chain order.
TEST(RobotCheck, TheOneAndTheThreeJointRobotsPosesAndDrivesHaveNoError) {
  for (const char* name : {"intake-pivot", "reefscape-2025-elevator-pivot-wrist"}) {
    const config::Config config = robotNamed(name);
    RobotCheck check;
    check.poses = checkPoseClearances(config);
    check.drives = checkDrives(config.robot, heaviestPieces(config.robot));
    EXPECT_EQ(check.count(Severity::kError), 0) << name << "\n" << robotReportText(config, check);
    ASSERT_EQ(check.drives.size(), static_cast<size_t>(config.robot.jointCount())) << name;
    for (int j = 0; j < config.robot.jointCount(); ++j) {
      const DriveCheck& d = check.drives[static_cast<size_t>(j)];
      EXPECT_EQ(d.joint, config.robot.joints[j].name) << name;
      EXPECT_EQ(d.worst_q.size(), config.robot.jointCount()) << name << " " << d.joint;
      EXPECT_GT(d.hold_volts, 0.0) << name << " " << d.joint;
      EXPECT_GT(d.worst_acceleration, 0.0) << name << " " << d.joint;
    }
  }
}

// The intake's moves between its named poses, planned for one joint.
TEST(RobotCheck, TheOneJointRobotsPosesJoinBothWays) {
  const config::Config config = robotNamed("intake-pivot");
  const RobotCheck check = fullCheck(config);
  EXPECT_EQ(check.count(Severity::kError), 0) << robotReportText(config, check);
  ASSERT_EQ(check.reach.size(), config.poses.size());
  for (const PoseSetReach& r : check.reach) {
    EXPECT_EQ(r.pairs_planned, r.poses * (r.poses - 1)) << r.pose_set << "\n" << robotReportText(config, check);
    EXPECT_EQ(r.groups.size(), 1U) << r.pose_set;
  }
}

// A wrist on a 1 A limit cannot hold the effector level: the error names the wrist and the pose
// by its three values.
TEST(RobotCheck, AWeakWristIsAnErrorNamingItsPose) {
  const config::Config config =
      robotWith("reefscape-2025-elevator-pivot-wrist", "current_limit_amps = 50.0", "current_limit_amps = 1.0");
  RobotCheck check;
  check.drives = checkDrives(config.robot, heaviestPieces(config.robot));
  ASSERT_EQ(check.drives.size(), 3U);
  EXPECT_EQ(check.drives[0].severity, Severity::kOk);
  EXPECT_EQ(check.drives[1].severity, Severity::kOk);
  EXPECT_EQ(check.drives[2].severity, Severity::kError);
  const std::string text = robotReportText(config, check);
  const size_t at = text.find("error: drive wrist cannot hold its load or move both ways at (");
  ASSERT_NE(at, std::string::npos) << text;
  const std::string pose = text.substr(at, text.find(')', at) - at);
  EXPECT_EQ(std::count(pose.begin(), pose.end(), ','), 2) << pose;
}

TEST(RobotCheck, AWeakIntakePivotIsAnError) {
  const config::Config config = robotWith("intake-pivot", "current_limit_amps = 40.0", "current_limit_amps = 5.0");
  const std::vector<DriveCheck> drives = checkDrives(config.robot, heaviestPieces(config.robot));
  ASSERT_EQ(drives.size(), 1U);
  EXPECT_EQ(drives[0].severity, Severity::kError);
  EXPECT_EQ(drives[0].worst_q.size(), 1);
}

// The drive check's grid: the joint limits and each range's middle, and for three joints no more
// poses than two joints take (docs/configuration.md, "Checking a robot").
TEST(RobotCheck, TheDriveGridOfThreeJointsStaysWithinTheWorkOfTwo) {
  EXPECT_EQ(driveSamplesPerJoint(1), 49);
  EXPECT_EQ(driveSamplesPerJoint(2), 49);
  const int three = driveSamplesPerJoint(3);
  EXPECT_EQ(three % 2, 1);
  EXPECT_LE(three * three * three, 49 * 49);
  EXPECT_GE(three * three * three, 49 * 49 * 3 / 4) << "much coarser than it needs to be";
}

TEST(RobotCheck, TheHeaviestSetHoldsEveryPieceWithMass) {
  const config::Config& config = test::shippedRobot("chargedup-2023-double-jointed").config;
  EXPECT_EQ(config.robot.pieceSetName(heaviestPieces(config.robot)), "cone+cube");
}

}  // namespace
}  // namespace cyber::tools

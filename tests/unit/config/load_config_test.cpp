// The TOML loader: the reference robot loads with its exact numbers, and every kind of bad file
// fails at load with a message that names the key and the problem.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <string>

#include "cyber/config/load_config.hpp"

namespace cyber::config {
namespace {

std::string defaultText() { return std::string(embeddedDefaultConfig()); }

// Replaces the first occurrence of `from` (which must exist) in the default text.
std::string mutated(const std::string& from, const std::string& to) {
  std::string text = defaultText();
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "fixture text not found: " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(LoadConfig, EmbeddedDefaultIsTheReferenceRobot) {
  const Config config = loadEmbeddedDefaultConfig();
  const planner::RobotModel& r = config.robot;
  EXPECT_EQ(r.name, "reefscape-2025");
  EXPECT_DOUBLE_EQ(r.clearance_m, 0.03);
  EXPECT_DOUBLE_EQ(r.range(0).max, 2.0);
  EXPECT_DOUBLE_EQ(r.range(1).max, 6.108652381980153);
  EXPECT_EQ(r.joints[0].name, "elevator");
  EXPECT_EQ(r.joints[0].type, planner::JointType::kPrismatic);
  EXPECT_NEAR(r.joints[0].axis_rad, 80.0 * std::numbers::pi / 180.0, 1e-15);
  EXPECT_EQ(r.joints[0].origin_m, planner::Point2(-0.4, 0.2));
  EXPECT_EQ(r.joints[1].name, "arm");
  EXPECT_EQ(r.joints[1].type, planner::JointType::kRevolute);
  ASSERT_EQ(r.links.size(), 1u);
  EXPECT_EQ(r.links[0].joint, 1);
  ASSERT_EQ(r.links[0].polygons.size(), 1u);
  EXPECT_EQ(r.links[0].polygons[0].size(), 4);
  ASSERT_GE(r.pieceIndex("algae"), 0);
  ASSERT_GE(r.pieceIndex("coral"), 0);
  EXPECT_EQ(r.pieces[static_cast<size_t>(r.pieceIndex("algae"))].polygons[0].size(), 8);
  ASSERT_EQ(r.scenes.size(), 2u);
  EXPECT_EQ(r.scenes[0].name, "reef");
  EXPECT_EQ(r.scenes[0].obstacles.size(), 6u);
  EXPECT_EQ(r.scenes[0].fixed.size(), 2u);
  EXPECT_DOUBLE_EQ(r.scenes[0].offset_range_m.max, 0.3);
  EXPECT_EQ(r.scenes[1].obstacles.size(), 0u);
  // Robot polygons are clockwise in the file; the model stores them counter-clockwise.
  const auto& v = r.links[0].polygons[0].vertices();
  double twice_area = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    const auto& a = v[i];
    const auto& b = v[(i + 1) % v.size()];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  EXPECT_NEAR(twice_area, 2 * 0.45 * 0.15, 1e-12);  // trapezoid of heights 0.1 and 0.2 over 0.45 m

  const planner::DriveParams& e = r.drive(0);
  EXPECT_EQ(e.motor_count, 2);
  EXPECT_DOUBLE_EQ(e.gearing, 200.0);
  EXPECT_DOUBLE_EQ(e.kV, 3.93);
  EXPECT_DOUBLE_EQ(e.current_limit_amps, 80.0);
  EXPECT_EQ(e.gravity, planner::GravityModel::kConstant);
  EXPECT_EQ(r.drive(1).gravity, planner::GravityModel::kCosine);
  // Derived motor constants of the Kraken X60 FOC as WPILib gives them.
  EXPECT_NEAR(e.motor.resistanceOhms(), 12.0 / 483.0, 1e-15);
  EXPECT_NEAR(e.motor.kvRadpsPerVolt(), (5800.0 * 2 * std::numbers::pi / 60.0) / (12.0 - 2.0 * 12.0 / 483.0), 1e-9);
  EXPECT_FALSE(e.velocity_limit.has_value());

  EXPECT_EQ(config.daemon.devices.joints[0], 1);
  EXPECT_EQ(config.daemon.devices.joints[1], 2);
  EXPECT_EQ(config.daemon.devices.status, 3);
  EXPECT_EQ(config.daemon.channels.goal, "ARM_GOAL");
  EXPECT_EQ(config.daemon.channels.cancel, "ARM_CANCEL");
  EXPECT_DOUBLE_EQ(config.daemon.stream_rate_hz, 200.0);
  EXPECT_DOUBLE_EQ(config.daemon.heartbeat_timeout_s, 0.1);
}

TEST(LoadConfig, LoadsTheSameFromAFile) {
  const std::string path = ::testing::TempDir() + "/robot.toml";
  {
    std::ofstream out(path);
    out << defaultText();
  }
  const Config config = loadConfigFile(path);
  EXPECT_EQ(config.robot.name, "reefscape-2025");
  std::remove(path.c_str());
}

// Optional, so configurations written before it still load; off unless set.
TEST(LoadConfig, SetpointEchoFullRateIsOptionalAndOffByDefault) {
  EXPECT_FALSE(loadEmbeddedDefaultConfig().daemon.setpoint_echo_full_rate);
  const std::string without = mutated("setpoint_echo_full_rate = false", "");
  EXPECT_EQ(without.find("setpoint_echo_full_rate"), std::string::npos);
  EXPECT_FALSE(parseConfig(without, "robot.toml").daemon.setpoint_echo_full_rate);
  EXPECT_TRUE(parseConfig(mutated("setpoint_echo_full_rate = false", "setpoint_echo_full_rate = true"), "robot.toml")
                  .daemon.setpoint_echo_full_rate);
}

// Optional; without it the heartbeat is read in Systemcore's layout, the safe reading on either
// controller (docs/can-protocol.md, "Robot heartbeat").
TEST(LoadConfig, RobotControllerIsOptionalAndSystemcoreByDefault) {
  EXPECT_EQ(loadEmbeddedDefaultConfig().daemon.robot_controller, RobotController::kRoboRio);
  const std::string line = "robot_controller = \"roborio\"";
  ASSERT_NE(defaultText().find(line), std::string::npos);
  EXPECT_EQ(parseConfig(mutated(line, ""), "robot.toml").daemon.robot_controller, RobotController::kSystemcore);
  EXPECT_EQ(DaemonSettings{}.robot_controller, RobotController::kSystemcore);
  EXPECT_EQ(parseConfig(mutated(line, "robot_controller = \"systemcore\""), "robot.toml").daemon.robot_controller,
            RobotController::kSystemcore);
}

TEST(LoadConfig, MaxPlanningBudgetIsOptionalWithADefaultOfOneSecond) {
  EXPECT_EQ(loadEmbeddedDefaultConfig().daemon.max_planning_budget_s, 1.0);
  const std::string with = mutated("[daemon]\n", "[daemon]\nmax_planning_budget_s = 3.0\n");
  EXPECT_EQ(parseConfig(with, "robot.toml").daemon.max_planning_budget_s, 3.0);
}

// Optional (added with ARM_CANCEL, issue 25), so configurations written before it still load.
TEST(LoadConfig, TheCancelChannelIsOptionalAndCanBeRenamed) {
  EXPECT_EQ(loadEmbeddedDefaultConfig().daemon.channels.cancel, "ARM_CANCEL");
  const std::string renamed = defaultText() + "[daemon.channels]\ncancel = \"LEFT_ARM_CANCEL\"\n";
  EXPECT_EQ(parseConfig(renamed, "robot.toml").daemon.channels.cancel, "LEFT_ARM_CANCEL");
  EXPECT_THROW((void)parseConfig(defaultText() + "[daemon.channels]\ncancel = \"\"\n", "robot.toml"), ConfigError);
}

// A description in the format before joint chains fails naming the keys that replace its own.
TEST(LoadConfig, TheFormatBeforeChainsIsRefusedNamingTheNewKeys) {
  const std::string old_format =
      "name = \"old\"\nclearance_m = 0.03\n[joints.elevator]\nmin_m = 0.0\nmax_m = 2.0\ntilt_deg = 80.0\n"
      "base_m = [-0.4, 0.2]\n[joints.arm]\nmin_rad = 0.0\nmax_rad = 6.1\n[robot]\narm = [[[0, 0], [1, 0], [0, 1]]]\n";
  try {
    (void)parseConfig(old_format, "old.toml");
    FAIL() << "the old format was accepted";
  } catch (const ConfigError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.key(), "joints");
    for (const char* key : {"[[joints]]", "type", "origin_m", "axis_deg", "[links.NAME]", "[pieces.NAME]"}) {
      EXPECT_NE(message.find(key), std::string::npos) << key << " not named: " << message;
    }
  }
}

TEST(LoadConfig, MissingFileIsAnError) {
  try {
    (void)loadConfigFile("/nonexistent/robot.toml");
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos) << e.what();
  }
}

struct BadCase {
  const char* name;
  const char* from;
  const char* to;
  const char* key;      // must appear in the message
  const char* problem;  // must appear in the message
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

// The reference file's last line, after which the device cases add a [daemon.devices] table.
constexpr const char* kLastLine = "log_level = \"info\"\n";

class BadConfig : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadConfig, FailsNamingKeyAndProblem) {
  const BadCase& c = GetParam();
  try {
    (void)parseConfig(mutated(c.from, c.to), "robot.toml");
    FAIL() << "expected ConfigError for " << c.name;
  } catch (const ConfigError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(c.key), std::string::npos) << message;
    EXPECT_NE(message.find(c.problem), std::string::npos) << message;
    EXPECT_EQ(message.rfind("robot.toml", 0), 0u) << message;
  }
}

const BadCase kBadCases[] = {
    {"UnknownTopKey", "clearance_m = 0.03", "clearance_m = 0.03\nclearence = 1", "clearence", "unknown key"},
    {"UnknownNestedKey", "kS_volts = 0.15", "kS_volts = 0.15\nks = 0.1", "drives.elevator.ks", "unknown key"},
    {"MissingKey", "clearance_m = 0.03\n", "", "clearance_m", "missing key"},
    {"MissingNestedKey", ", axis_deg = 80.0", "", "joints[0].axis_deg", "missing key"},
    {"WrongType", "clearance_m = 0.03", "clearance_m = \"thin\"", "clearance_m", "expected a number"},
    {"WrongTypeInteger", "count = 2", "count = 2.5", "drives.elevator.count", "expected an integer"},
    {"NotANumber", "kV = 3.93", "kV = nan", "drives.elevator.kV", "finite"},
    {"Infinite", "max = 2.0", "max = inf", "joints[0].max", "finite"},
    {"NegativeClearance", "clearance_m = 0.03", "clearance_m = -0.01", "clearance_m", "out of range"},
    {"InvertedRange", "max = 2.0", "max = -1.0", "joints[0].max", "out of range"},
    {"UnknownJointType", "type = \"prismatic\"", "type = \"telescopic\"", "joints[0].type", "expected \"prismatic\""},
    {"FourJoints", "  { name = \"arm\"",
     "  { name = \"a\", type = \"revolute\", min = 0.0, max = 1.0, origin_m = [0.0, 0.0], axis_deg = 0.0 },\n"
     "  { name = \"b\", type = \"revolute\", min = 0.0, max = 1.0, origin_m = [0.0, 0.0], axis_deg = 0.0 },\n"
     "  { name = \"arm\"",
     "joints", "expected one to 3 joints, in chain order (got 4)"},
    {"SameJointNames", "name = \"arm\", type", "name = \"elevator\", type", "joints[1].name", "its own name"},
    {"UnknownJointOfLink", "arm = { joint = \"arm\"", "arm = { joint = \"wrist\"", "links.arm.joint",
     "unknown joint \"wrist\""},
    {"UnknownJointOfPiece", "coral = { joint = \"arm\"", "coral = { joint = \"claw\"", "pieces.coral.joint",
     "unknown joint"},
    {"JointNameWithNul", "name = \"arm\", type", "name = \"a\\u0000rm\", type", "joints[1].name", "control characters"},
    {"SceneNameWithNewline", "name = \"reef\"", "name = \"re\\nef\"", "scenes[0].name", "control characters"},
    {"PieceNameWithTab", "coral = {", "\"co\\tral\" = {", "pieces.co\tral", "control characters"},
    {"PieceNameWithPlus", "coral = {", "\"co+ral\" = {", "pieces.co+ral", "'+'"},
    {"MissingDrive", "[drives.arm]", "[drives.wrist]", "drives.arm", "every joint needs a drive"},
    {"UnknownDriveKind", "kind = \"feedforward\"\nmotor = \"kraken_x60_foc\"\ncount = 1",
     "kind = \"magic\"\nmotor = \"kraken_x60_foc\"\ncount = 1", "drives.arm.kind", "expected \"feedforward\""},
    {"OffsetRangeWithoutZero", "offset_range_m = [0.0, 0.3]", "offset_range_m = [0.1, 0.3]", "scenes[0].offset_range_m",
     "min <= 0 <= max"},
    {"UnknownFixedObstacle", "fixed = [\"drivetrain_keepout\", \"floor\"]\noffset",
     "fixed = [\"drivetrain_keepout\", \"flor\"]\noffset", "scenes[0].fixed", "unknown obstacle \"flor\""},
    {"ZeroGearing", "gearing = 200.0", "gearing = 0.0", "drives.elevator.gearing", "out of range"},
    {"StreamRate", "[daemon]\n", "[daemon]\nstream_rate_hz = 0.0\n", "daemon.stream_rate_hz", "out of range"},
    {"FullRateEchoType", "setpoint_echo_full_rate = false", "setpoint_echo_full_rate = 1",
     "daemon.setpoint_echo_full_rate", "expected true or false"},
    {"MaxBudgetBelowBudget", "[daemon]\n", "[daemon]\nmax_planning_budget_s = 0.01\n", "daemon.max_planning_budget_s",
     "out of range"},
    {"MaxBudgetTooLarge", "[daemon]\n", "[daemon]\nmax_planning_budget_s = 11.0\n", "daemon.max_planning_budget_s",
     "out of range"},
    {"DeviceNumber", kLastLine,
     "log_level = \"info\"\n[daemon.devices]\n"
     "elevator = 64\narm = 2\nstatus = 3\n",
     "daemon.devices.elevator", "out of range"},
    {"NonConvex", "l1_trough = [[0.0, 0.0], [0.248, 0.0], [0.248, 0.514], [0.0, 0.454]]",
     "l1_trough = [[0.0, 0.0], [0.248, 0.0], [0.1, 0.1], [0.248, 0.514], [0.0, 0.454]]", "obstacles.l1_trough",
     "not convex"},
    {"TwoVertices", "l4_post = [[0.03, 1.637], [0.072, 1.637], [0.072, 1.81], [0.03, 1.81]]",
     "l4_post = [[0.03, 1.637], [0.072, 1.637]]", "obstacles.l4_post", "at least 3 vertices"},
    {"BadVertex", "[0.25, 0.1], [0.25, -0.1]", "[0.25, 0.1, 0.3], [0.25, -0.1]", "links.arm.polygons[0][1]", "pair"},
    {"EmptyLink", "polygons = [[[-0.2, 0.05], [0.25, 0.1], [0.25, -0.1], [-0.2, -0.05]]]", "polygons = []",
     "links.arm.polygons", "at least one polygon"},
    {"UnknownObstacleInScene", "obstacles = [\"l1_trough\",", "obstacles = [\"l1_trouf\",", "scenes[0].obstacles",
     "unknown obstacle \"l1_trouf\""},
    {"UnknownMotor", "motor = \"kraken_x60_foc\"", "motor = \"neo\"", "drives.elevator.motor", "unknown motor"},
    {"WrongGravity", "gravity = \"cosine\"", "gravity = \"tangent\"", "drives.arm.gravity", "\"sine\""},
    {"CannotHold", "current_limit_amps = 60.0", "current_limit_amps = 0.5", "drives.arm.current_limit_amps", "hold"},
    {"BadLogLevel", "log_level = \"info\"", "log_level = \"loud\"", "daemon.log_level", "expected one of"},
    {"BadRobotController", "robot_controller = \"roborio\"", "robot_controller = \"rio\"", "daemon.robot_controller",
     "expected \"roborio\" or \"systemcore\""},
    {"SameDevices", kLastLine,
     "log_level = \"info\"\n[daemon.devices]\n"
     "elevator = 1\narm = 1\nstatus = 3\n",
     "daemon.devices", "must differ"},
    // [daemon.devices] is keyed by the config's joint names (and status), nothing else.
    {"DeviceOfNoJoint", kLastLine,
     "log_level = \"info\"\n[daemon.devices]\n"
     "elevator = 1\narm = 2\nstatus = 3\nwrist = 4\n",
     "daemon.devices.wrist",
     "not a joint of this robot; [daemon.devices] takes one key per joint, `elevator`, `arm`, "
     "and `status`"},
    {"DeviceOfARenamedJoint", kLastLine,
     "log_level = \"info\"\n[daemon.devices]\n"
     "lift = 1\narm = 2\nstatus = 3\n",
     "daemon.devices.lift", "not a joint of this robot"},
    {"DeviceOfAJointMissing", kLastLine,
     "log_level = \"info\"\n[daemon.devices]\n"
     "elevator = 1\nstatus = 3\n",
     "daemon.devices.arm", "missing: [daemon.devices] takes one key per joint, `elevator`, `arm`, and `status`"},
    {"ParseError", "clearance_m = 0.03", "clearance_m = = 0.03", "robot.toml:", "robot.toml"},
};

INSTANTIATE_TEST_SUITE_P(Cases, BadConfig, ::testing::ValuesIn(kBadCases),
                         [](const ::testing::TestParamInfo<BadCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace cyber::config

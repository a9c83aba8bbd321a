// What a team sees when its own robot's file is wrong (issue 35): each message names the key and
// the likely fix; and a file without [planner] or [daemon] loads with every default, each logged
// with where it came from.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "cyber/config/load_config.hpp"
#include "shipped_robots.hpp"

namespace cyber::config {
namespace {

std::string minimalText() {
  std::ifstream in(test::sourceFile("tests/fixtures/minimal-robot.toml"));
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string replaced(const std::string& from, const std::string& to) {
  std::string text = minimalText();
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The whole message (after "robot.toml: ") and its key.
void expectMessage(const std::string& text, const std::string& key, const std::string& message) {
  try {
    (void)parseConfig(text, "robot.toml");
    ADD_FAILURE() << "accepted; expected " << message;
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), key);
    EXPECT_EQ(std::string(e.what()), "robot.toml: " + key + ": " + message);
  }
}

TEST(ConfigMessages, AKeyWithoutItsUnitIsNamedWithTheKeyMeant) {
  expectMessage(replaced("origin_m = [0.0, 0.0]", "origin = [0.0, 0.0]"), "joints[1].origin",
                "unknown key 'origin' (did you mean 'origin_m'?)");
  expectMessage(replaced("kS_volts = 0.1\nkG_volts = 0.2", "ks = 0.1\nkG_volts = 0.2"), "drives.arm.ks",
                "unknown key 'ks' (did you mean 'kS_volts'?)");
}

TEST(ConfigMessages, AMisspelledOptionalKeyIsNamedWithTheKeyMeant) {
  expectMessage(minimalText() + "[planner.search]\npotential_rnage = 0.2\n", "planner.search.potential_rnage",
                "unknown key 'potential_rnage' (did you mean 'potential_range'?)");
  expectMessage(minimalText() + "[daemon]\nlcm_uri = \"udpm://239.255.76.67:5810?ttl=1\"\n", "daemon.lcm_uri",
                "unknown key 'lcm_uri' (did you mean 'lcm_url'?)");
  // Nothing close: no guess.
  expectMessage(minimalText() + "[daemon]\nshooter = 1\n", "daemon.shooter", "unknown key 'shooter'");
}

TEST(ConfigMessages, ALinksJointMustBeAJointsName) {
  expectMessage(replaced("joint = \"arm\"", "joint = 1"), "links.arm.joint",
                "expected a joint's name as a string, \"lift\" or \"arm\"");
}

// A drive's link gives all its mass data: a left-out moment of inertia would silently understate
// the torque. A game piece is a point mass at its cg unless it says more.
TEST(ConfigMessages, ARigidBodyDriveNeedsItsMomentOfInertia) {
  const std::string rigid =
      "kind = \"rigid_body\"\nmotor = \"kraken_x60\"\ncount = 1\ngearing = 50.0\nkS_volts = 0.1\n"
      "mass_kg = 2.0\ncg_m = 0.2\nmoi_kgm2 = 0.05\nvoltage_limit_volts = 12.0\n";
  std::string text = minimalText();
  text = text.substr(0, text.find("[drives.lift]")) + "[drives.lift]\n" + rigid + "current_limit_amps = 60.0\n" +
         "[drives.arm]\n" + rigid + "current_limit_amps = 40.0\n" + text.substr(text.find("[poses.none]"));
  EXPECT_DOUBLE_EQ(parseConfig(text, "robot.toml").robot.bodies[1].moi_kgm2, 0.05);
  std::string without = text;
  without.erase(without.rfind("moi_kgm2 = 0.05\n"), 16);
  expectMessage(without, "drives.arm.moi_kgm2", "missing key");
}

TEST(ConfigMessages, AFileWithoutPlannerOrDaemonTakesEveryDefault) {
  const Config config = parseConfig(minimalText(), "minimal-robot.toml");
  EXPECT_EQ(config.daemon.lcm_url, "udpm://239.255.76.67:5810?ttl=0");
  EXPECT_EQ(config.daemon.devices.joints[0], 1);
  EXPECT_EQ(config.daemon.devices.joints[1], 2);
  EXPECT_EQ(config.daemon.devices.status, 3);
  EXPECT_EQ(config.daemon.channels.goal, "ARM_GOAL");
  int derived = 0;
  for (const SettingOrigin& s : config.settings) {
    EXPECT_NE(s.source, SettingSource::kGiven) << s.key;
    if (s.source == SettingSource::kDerived) ++derived;
  }
  EXPECT_EQ(derived, 6);  // metric, grid step, potential range, three device numbers
  const auto value = [&](const std::string& key) {
    for (const SettingOrigin& s : config.settings) {
      if (s.key == key) return s.value + " " + sourceName(s.source);
    }
    return std::string("none");
  };
  EXPECT_EQ(value("planner.metric"), "[1, 0.25] derived");
  EXPECT_EQ(value("planner.grid.step"), "[0.04, 0.08] derived");
  EXPECT_EQ(value("planner.search.potential_range"), "0.2 derived");
  EXPECT_EQ(value("planner.topp.grid_points"), "200 default");
  EXPECT_EQ(value("daemon.lcm_url"), "\"udpm://239.255.76.67:5810?ttl=0\" default");
  EXPECT_EQ(value("daemon.devices.lift"), "1 derived");
  EXPECT_EQ(value("daemon.devices.status"), "3 derived");
  // What the planner runs with.
  EXPECT_EQ(config.robot.planner.metric, (planner::JointVector{{1.0, 0.25}}));
  EXPECT_EQ(config.robot.planner.grid.step, (planner::JointVector{{0.04, 0.08}}));
  EXPECT_DOUBLE_EQ(config.robot.planner.search.potential_range, 0.2);
}

TEST(ConfigMessages, AGivenKeyIsLoggedAsGiven) {
  const Config config = parseConfig(minimalText() + "[planner]\nmetric = [1.0, 0.5]\n", "robot.toml");
  EXPECT_EQ(config.robot.planner.metric, (planner::JointVector{{1.0, 0.5}}));
  EXPECT_EQ(config.settings.front().key, "planner.metric");
  EXPECT_EQ(config.settings.front().source, SettingSource::kGiven);
}

}  // namespace
}  // namespace cyber::config

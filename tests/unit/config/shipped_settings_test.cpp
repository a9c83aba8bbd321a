// The shipped robots' files shrank to the keys that differ from the defaults (docs/configuration.md,
// "Defaults"): each must still load to the settings its old file spelled out, bit for bit, so that
// no plan changes. The old [planner] and [daemon] tables are stored here as they were.

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "cyber/config/load_config.hpp"
#include "shipped_robots.hpp"

namespace cyber::config {
namespace {

// The [planner] table all three files had, but for `metric`.
constexpr const char* kOldPlanner = R"(
[planner]
metric = METRIC
[planner.grid]
step = [0.02, 0.02]
[planner.search]
potential_weight = 2.0
potential_range = 0.15
[planner.smoothing]
waypoint_spacing = 0.05
obstacle_weight = 0.5
obstacle_decay_m = 0.03
prior_weight = 20.0
length_weight = 1.0
smoothness_weight = 1000.0
max_iterations = 200
gradient_tolerance = 1e-6
relative_cost_tolerance = 1e-9
lead_in_time_s = 0.1
max_lead_in = 0.3
[planner.topp]
grid_points = 200
primal_tolerance = 1e-6
dual_tolerance = 1e-4
max_outer_iterations = 50
max_inner_iterations = 500
limit_check_step_s = 0.001
limit_check_tolerance = 0.005
max_limit_refinements = 8
penalty_initial = 1e3
penalty_growth = 1.0
penalty_max = 1e6
)";

// Their [daemon] table: the reference robot's had the controller; the other two had LCM's own port
// 7667, which the robot program's ROBOT_LAN_URL (5810) never heard: they now take the default.
constexpr const char* kOldDaemon = R"(
[daemon]
lcm_url = "udpm://239.255.76.67:5810?ttl=0"
can_interface = "can0"
stream_rate_hz = 200.0
state_timeout_s = 0.25
heartbeat_timeout_s = 0.1
require_robot_enabled = true
CONTROLLER
planning_budget_s = 0.03
status_rate_hz = 10.0
setpoint_echo_rate_hz = 50.0
setpoint_echo_full_rate = false
trajectory_step_s = 0.01
log_level = "info"
[daemon.devices]
JOINT0 = 1
JOINT1 = 2
status = 3
[daemon.channels]
goal = "ARM_GOAL"
state = "ARM_STATE"
plan_status = "ARM_PLAN_STATUS"
trajectory = "ARM_TRAJECTORY"
setpoint = "ARM_SETPOINT"
daemon_status = "ARM_DAEMON_STATUS"
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

// The file without its [planner...] and [daemon...] tables.
std::string withoutSettings(const std::string& text) {
  std::istringstream in(text);
  std::string out;
  bool skipping = false;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("[")) skipping = line.starts_with("[planner") || line.starts_with("[daemon");
    if (!skipping) out.append(line).append("\n");
  }
  return out;
}

std::map<std::string, std::string> settingValues(const Config& config) {
  std::map<std::string, std::string> out;
  for (const SettingOrigin& s : config.settings) out[s.key] = s.value;
  return out;
}

struct Shipped {
  const char* name;
  const char* metric;
  const char* controller;
};

TEST(ShippedSettings, EveryShippedRobotLoadsTheSettingsOfItsOldFile) {
  for (const Shipped& robot :
       {Shipped{"reefscape-2025", "[1.0, 0.1]", "robot_controller = \"roborio\""},
        Shipped{"chargedup-2023-double-jointed", "[1.0, 0.4]", ""}, Shipped{"pivot-telescope", "[1.0, 0.4]", ""}}) {
    const std::string path = test::sourceFile(std::string("config/") + robot.name + ".toml");
    std::ifstream in(path);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const Config now = parseConfig(text, path);
    std::string daemon = replaced(kOldDaemon, "CONTROLLER", robot.controller);
    daemon = replaced(replaced(daemon, "JOINT0", now.robot.joints[0].name), "JOINT1", now.robot.joints[1].name);
    const Config old =
        parseConfig(withoutSettings(text) + replaced(kOldPlanner, "METRIC", robot.metric) + daemon, "old");
    const auto now_values = settingValues(now);
    const auto old_values = settingValues(old);
    ASSERT_EQ(now_values.size(), old_values.size()) << robot.name;
    for (const auto& [key, value] : old_values) {
      // Shortest round-trip text: equal text is the same double.
      EXPECT_EQ(now_values.at(key), value) << robot.name << ": " << key;
    }
    EXPECT_EQ(now.daemon.lcm_url, kDefaultLcmUrl) << robot.name;
  }
}

// A key equal to what it would be without it is boilerplate a team would copy without knowing why:
// the shipped files give only the [planner] keys that differ.
TEST(ShippedSettings, NoShippedPlannerKeyRepeatsItsDefault) {
  for (const char* name : test::kShippedRobotNames) {
    const std::string path = test::sourceFile(std::string("config/") + name + ".toml");
    std::ifstream in(path);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const auto given = settingValues(parseConfig(text, path));
    const Config bare = parseConfig(withoutSettings(text), path);
    for (const SettingOrigin& s : parseConfig(text, path).settings) {
      if (s.source != SettingSource::kGiven || !s.key.starts_with("planner.")) continue;
      const auto it = std::find_if(bare.settings.begin(), bare.settings.end(),
                                   [&](const SettingOrigin& b) { return b.key == s.key; });
      ASSERT_NE(it, bare.settings.end()) << s.key;
      EXPECT_NE(it->value, s.value) << name << ": " << s.key << " repeats its " << sourceName(it->source) << " value";
    }
    EXPECT_FALSE(given.empty());
  }
}

}  // namespace
}  // namespace cyber::config

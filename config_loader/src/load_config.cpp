#include "cyber/config/load_config.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>

#include "read_chain.hpp"
#include "read_drives.hpp"
#include "table_reader.hpp"

namespace cyber::config {
namespace {

using detail::Bounds;
using detail::kNonNegative;
using detail::kPositive;
using detail::TableReader;
using planner::RobotModel;

void readPlanner(TableReader p, planner::PlannerSettings& s) {
  s.metric = p.vector2("metric", kPositive);
  {
    TableReader g = p.table("grid");
    s.grid.step = g.vector2("step", Bounds{1e-4, 0.5});
    g.finish();
  }
  {
    TableReader g = p.table("search");
    s.search.potential_weight = g.number("potential_weight", kNonNegative);
    s.search.potential_range = g.number("potential_range", kPositive);
    if (g.has("offset_band_clearances")) {
      s.search.offset_band_clearances = g.number("offset_band_clearances", Bounds{0.5, 20.0});
    }
    g.finish();
  }
  {
    TableReader g = p.table("smoothing");
    s.smoothing.waypoint_spacing = g.number("waypoint_spacing", Bounds{1e-3, 1.0});
    s.smoothing.obstacle_weight = g.number("obstacle_weight", kNonNegative);
    s.smoothing.obstacle_decay_m = g.number("obstacle_decay_m", kPositive);
    s.smoothing.prior_weight = g.number("prior_weight", kNonNegative);
    s.smoothing.length_weight = g.number("length_weight", kNonNegative);
    s.smoothing.smoothness_weight = g.number("smoothness_weight", kNonNegative);
    s.smoothing.max_iterations = static_cast<int>(g.integer("max_iterations", 0, 100000));
    s.smoothing.gradient_tolerance = g.number("gradient_tolerance", kPositive);
    s.smoothing.relative_cost_tolerance = g.number("relative_cost_tolerance", Bounds{0.0, 1.0});
    s.smoothing.lead_in_time_s = g.number("lead_in_time_s", Bounds{0.0, 1.0});
    s.smoothing.max_lead_in = g.number("max_lead_in", Bounds{0.0, 2.0});
    g.finish();
  }
  {
    TableReader g = p.table("topp");
    s.topp.grid_points = static_cast<int>(g.integer("grid_points", 8, 100000));
    s.topp.solver.primal_tolerance = g.number("primal_tolerance", kPositive);
    s.topp.solver.dual_tolerance = g.number("dual_tolerance", kPositive);
    s.topp.solver.max_outer_iterations = static_cast<int>(g.integer("max_outer_iterations", 1, 100000));
    s.topp.solver.max_inner_iterations = static_cast<int>(g.integer("max_inner_iterations", 1, 1000000));
    s.topp.limit_check_step_s = g.number("limit_check_step_s", Bounds{1e-5, 0.01});
    s.topp.limit_check_tolerance = g.number("limit_check_tolerance", Bounds{0.0, 0.1});
    s.topp.max_limit_refinements = static_cast<int>(g.integer("max_limit_refinements", 0, 100));
    s.topp.solver.penalty_initial = g.number("penalty_initial", kPositive);
    s.topp.solver.penalty_growth = g.number("penalty_growth", kNonNegative);
    s.topp.solver.penalty_max = g.number("penalty_max", Bounds{s.topp.solver.penalty_initial, 1e300});
    g.finish();
  }
  p.finish();
}

// [daemon.devices]: a key per joint, by the joint's name, and `status`; nothing else, so a
// configuration written for another robot's joints fails here rather than driving the wrong ones.
void readDevices(TableReader dev, const RobotModel& robot, DeviceNumbers& devices) {
  std::string expected;
  for (const auto& joint : robot.joints) expected += "`" + joint.name + "`, ";
  expected += "and `status`";
  for (const std::string& key : dev.keys()) {
    if (key != "status" && robot.jointIndex(key) < 0) {
      dev.fail(key, "not a joint of this robot; [daemon.devices] takes one key per joint, " + expected);
    }
  }
  // FRC CAN device numbers are 6 bits; 63 is the broadcast device.
  for (size_t j = 0; j < devices.joints.size(); ++j) {
    const std::string& name = robot.joints[j].name;
    if (!dev.has(name)) dev.fail(name, "missing: [daemon.devices] takes one key per joint, " + expected);
    devices.joints[j] = static_cast<int>(dev.integer(name, 0, 62));
  }
  devices.status = static_cast<int>(dev.integer("status", 0, 62));
  if (devices.joints[0] == devices.joints[1] || devices.status == devices.joints[0] ||
      devices.status == devices.joints[1]) {
    dev.fail("status",
             "the device numbers of " + robot.joints[0].name + ", " + robot.joints[1].name + " and status must differ");
  }
  dev.finish();
}

DaemonSettings readDaemon(TableReader d, const RobotModel& robot) {
  DaemonSettings s;
  s.lcm_url = d.string("lcm_url");
  s.can_interface = d.string("can_interface");
  if (s.can_interface.empty() || s.can_interface.size() > 15) {
    d.fail("can_interface", "an interface name of 1 to 15 characters, e.g. \"can0\"");
  }
  s.stream_rate_hz = d.number("stream_rate_hz", Bounds{1.0, 1000.0});
  s.state_timeout_s = d.number("state_timeout_s", Bounds{0.001, 10.0});
  s.heartbeat_timeout_s = d.number("heartbeat_timeout_s", Bounds{0.001, 10.0});
  s.require_robot_enabled = d.boolean("require_robot_enabled");
  if (d.has("robot_controller")) {
    const std::string controller = d.string("robot_controller");
    if (controller == "roborio") {
      s.robot_controller = RobotController::kRoboRio;
    } else if (controller == "systemcore") {
      s.robot_controller = RobotController::kSystemcore;
    } else {
      d.fail("robot_controller", "expected \"roborio\" or \"systemcore\"");
    }
  }
  s.planning_budget_s = d.number("planning_budget_s", Bounds{0.0, 1.0});
  if (d.has("max_planning_budget_s")) {
    s.max_planning_budget_s = d.number("max_planning_budget_s", Bounds{s.planning_budget_s, 10.0});
  }
  s.status_rate_hz = d.number("status_rate_hz", Bounds{0.1, 100.0});
  s.setpoint_echo_rate_hz = d.number("setpoint_echo_rate_hz", Bounds{0.1, 1000.0});
  if (d.has("setpoint_echo_full_rate")) s.setpoint_echo_full_rate = d.boolean("setpoint_echo_full_rate");
  s.trajectory_step_s = d.number("trajectory_step_s", Bounds{0.001, 1.0});
  s.log_level = d.string("log_level");
  static const char* kLevels[] = {"trace", "debug", "info", "warn", "error", "critical", "off"};
  if (std::find(std::begin(kLevels), std::end(kLevels), s.log_level) == std::end(kLevels)) {
    d.fail("log_level", "expected one of trace, debug, info, warn, error, critical, off");
  }
  readDevices(d.table("devices"), robot, s.devices);
  {
    TableReader ch = d.table("channels");
    for (auto [key, field] :
         {std::pair{"goal", &s.channels.goal}, std::pair{"state", &s.channels.state},
          std::pair{"plan_status", &s.channels.plan_status}, std::pair{"trajectory", &s.channels.trajectory},
          std::pair{"setpoint", &s.channels.setpoint}, std::pair{"daemon_status", &s.channels.daemon_status}}) {
      *field = ch.string(key);
      if (field->empty()) ch.fail(key, "channel name must not be empty");
    }
    // Added after the others (issue 25): optional, so configurations written before it still load.
    if (ch.has("cancel")) {
      s.channels.cancel = ch.string("cancel");
      if (s.channels.cancel.empty()) ch.fail("cancel", "channel name must not be empty");
    }
    ch.finish();
  }
  d.finish();
  return s;
}

Config readRoot(const toml::table& root_table) {
  Config config;
  RobotModel& robot = config.robot;
  TableReader root(root_table, "");
  detail::rejectOldFormat(root);
  robot.name = root.string("name");
  robot.clearance_m = root.number("clearance_m", Bounds{0.0, 1.0});
  detail::readJoints(root, robot);
  detail::readLinks(root.table("links"), robot);
  if (root.has("pieces")) detail::readPieces(root.table("pieces"), robot);
  detail::readScenes(root, root.table("obstacles"), robot);
  detail::readDrives(root.table("motors"), root.table("drives"), robot);
  readPlanner(root.table("planner"), robot.planner);
  config.daemon = readDaemon(root.table("daemon"), robot);
  if (root.has("poses")) config.poses = detail::readPoses(root.table("poses"), robot);
  root.finish();
  return config;
}

}  // namespace

Config parseConfig(std::string_view toml_text, std::string_view source_name) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source_name);
  } catch (const toml::parse_error& e) {
    throw ConfigError(
        "", fmt::format("{}:{}:{}: {}", source_name, e.source().begin.line, e.source().begin.column, e.description()));
  }
  try {
    return readRoot(root);
  } catch (const ConfigError& e) {
    throw ConfigError(e.key(), std::string(source_name) + ": " + e.what());
  }
}

Config loadConfigFile(const std::string& path) {
  errno = 0;
  std::ifstream in(path);
  if (!in) throw ConfigError("", path + ": cannot open the configuration file (" + std::strerror(errno) + ")");
  // A directory opens but reads as empty, which would be reported as a missing key.
  if (std::filesystem::is_directory(path)) throw ConfigError("", path + ": is a directory, not a configuration file");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return parseConfig(text, path);
}

Config loadEmbeddedDefaultConfig() { return parseConfig(embeddedDefaultConfig(), embeddedDefaultConfigName()); }

}  // namespace cyber::config

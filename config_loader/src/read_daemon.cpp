#include "read_daemon.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>

#include "setting_reader.hpp"

namespace cyber::config::detail {
namespace {

std::string deviceKeys(const planner::RobotModel& robot) {
  std::string expected;
  for (const auto& joint : robot.joints) expected.append("`").append(joint.name).append("`, ");
  return expected.append("and `status`");
}

// [daemon.devices]: a key per joint, by the joint's name, and `status`; nothing else, so a
// configuration written for another robot's joints fails here rather than driving the wrong ones.
// Without the table: 1..N in joint order and N + 1 for the status frame.
void readDevices(TableReader dev, const planner::RobotModel& robot, DeviceNumbers& devices,
                 std::vector<SettingOrigin>& log) {
  SettingReader r(dev, log);
  devices.joints.assign(static_cast<size_t>(robot.jointCount()), 0);
  if (dev.keys().empty()) {
    for (size_t j = 0; j < devices.joints.size(); ++j) {
      devices.joints[j] = static_cast<int>(j) + 1;
      r.log(robot.joints[j].name, std::to_string(devices.joints[j]), SettingSource::kDerived);
    }
    devices.status = static_cast<int>(devices.joints.size()) + 1;
    r.log("status", std::to_string(devices.status), SettingSource::kDerived);
    return;
  }
  const std::string expected = deviceKeys(robot);
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
    r.log(name, std::to_string(devices.joints[j]), SettingSource::kGiven);
  }
  if (!dev.has("status")) dev.fail("status", "missing: [daemon.devices] takes one key per joint, " + expected);
  devices.status = static_cast<int>(dev.integer("status", 0, 62));
  r.log("status", std::to_string(devices.status), SettingSource::kGiven);
  std::vector<int> numbers = devices.joints;
  numbers.push_back(devices.status);
  std::sort(numbers.begin(), numbers.end());
  if (std::adjacent_find(numbers.begin(), numbers.end()) != numbers.end()) {
    std::string names;
    for (const auto& joint : robot.joints) names.append(joint.name).append(", ");
    dev.fail("status", fmt::format("the device numbers of {}and status must differ", names));
  }
  dev.finish();
}

void readChannels(TableReader ch, ChannelNames& channels, std::vector<SettingOrigin>& log) {
  SettingReader r(ch, log);
  for (auto [key, field] :
       {std::pair{"goal", &channels.goal}, std::pair{"cancel", &channels.cancel}, std::pair{"state", &channels.state},
        std::pair{"plan_status", &channels.plan_status}, std::pair{"trajectory", &channels.trajectory},
        std::pair{"setpoint", &channels.setpoint}, std::pair{"daemon_status", &channels.daemon_status}}) {
    r.string(key, *field);
    if (field->empty()) ch.fail(key, "channel name must not be empty");
  }
  ch.finish();
}

void readController(SettingReader& r, RobotController& controller) {
  std::string name = controller == RobotController::kRoboRio ? "roborio" : "systemcore";
  r.string("robot_controller", name);
  if (name == "roborio") {
    controller = RobotController::kRoboRio;
  } else if (name == "systemcore") {
    controller = RobotController::kSystemcore;
  } else {
    r.table().fail("robot_controller", "expected \"roborio\" or \"systemcore\"");
  }
}

}  // namespace

DaemonSettings readDaemon(TableReader d, const planner::RobotModel& robot, std::vector<SettingOrigin>& log) {
  DaemonSettings s;
  SettingReader r(d, log);
  r.string("lcm_url", s.lcm_url);
  r.string("can_interface", s.can_interface);
  if (s.can_interface.empty() || s.can_interface.size() > 15) {
    d.fail("can_interface", "an interface name of 1 to 15 characters, e.g. \"can0\"");
  }
  r.number("stream_rate_hz", s.stream_rate_hz, Bounds{1.0, 1000.0});
  r.number("state_timeout_s", s.state_timeout_s, Bounds{0.001, 10.0});
  r.number("heartbeat_timeout_s", s.heartbeat_timeout_s, Bounds{0.001, 10.0});
  r.boolean("require_robot_enabled", s.require_robot_enabled);
  readController(r, s.robot_controller);
  r.number("planning_budget_s", s.planning_budget_s, Bounds{0.0, 1.0});
  r.number("max_planning_budget_s", s.max_planning_budget_s, Bounds{s.planning_budget_s, 10.0});
  r.number("status_rate_hz", s.status_rate_hz, Bounds{0.1, 100.0});
  r.number("setpoint_echo_rate_hz", s.setpoint_echo_rate_hz, Bounds{0.1, 1000.0});
  r.boolean("setpoint_echo_full_rate", s.setpoint_echo_full_rate);
  r.number("trajectory_step_s", s.trajectory_step_s, Bounds{0.001, 1.0});
  r.string("log_level", s.log_level);
  static const char* kLevels[] = {"trace", "debug", "info", "warn", "error", "critical", "off"};
  if (std::find(std::begin(kLevels), std::end(kLevels), s.log_level) == std::end(kLevels)) {
    d.fail("log_level", "expected one of trace, debug, info, warn, error, critical, off");
  }
  readDevices(d.optionalTable("devices"), robot, s.devices, log);
  readChannels(d.optionalTable("channels"), s.channels, log);
  d.finish();
  return s;
}

}  // namespace cyber::config::detail

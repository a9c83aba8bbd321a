#pragma once
// The [daemon] section: how the daemon talks to LCM and CAN and how fast it streams.

#include <string>
#include <vector>

namespace cyber::config {

// The project's LCM URL: the team-use port 5810, this host only (ttl=0). The installed robot.toml
// has ttl=1 so the traffic reaches the robot's network (docs/lcm.md, "URL and port"). The project's
// programs default to it rather than to LCM's own default (port 7667).
inline constexpr char kDefaultLcmUrl[] = "udpm://239.255.76.67:5810?ttl=0";

// [daemon.devices]: one key per joint, named by the joint's [[joints]] name, and `status`. Without
// the table, 1..N in joint order and N + 1 for the status frame: these values.
struct DeviceNumbers {
  std::vector<int> joints{1, 2};  // setpoint frame of each joint (config order); the loader sets N
  int status = 3;                 // the daemon's own status frame
};

struct ChannelNames {
  std::string goal = "ARM_GOAL";
  std::string cancel = "ARM_CANCEL";
  std::string state = "ARM_STATE";
  std::string plan_status = "ARM_PLAN_STATUS";
  std::string trajectory = "ARM_TRAJECTORY";
  std::string setpoint = "ARM_SETPOINT";
  std::string daemon_status = "ARM_DAEMON_STATUS";
};

// Which robot controller sends the heartbeat that gates motion: its layout differs in one bit
// (docs/can-protocol.md, "Robot heartbeat").
enum class RobotController { kRoboRio, kSystemcore };

struct DaemonSettings {
  std::string lcm_url = kDefaultLcmUrl;
  std::string can_interface = "can0";
  double stream_rate_hz = 200.0;
  double state_timeout_s = 0.25;      // ARM_STATE older than this is stale: no motion
  double heartbeat_timeout_s = 0.1;   // robot-enabled gate (design.md: 100 ms)
  bool require_robot_enabled = true;  // false only for bench use without a roboRIO
  // Optional key, default Systemcore: its reading of the heartbeat is the safe one on either.
  RobotController robot_controller = RobotController::kSystemcore;
  double planning_budget_s = 0.03;  // how far ahead a mid-motion replan starts
  // The most the measured budget may grow to (a slow coprocessor or an emulated one plans
  // slower). Optional key, default 1 s.
  double max_planning_budget_s = 1.0;
  double status_rate_hz = 10.0;
  double setpoint_echo_rate_hz = 50.0;  // ARM_SETPOINT copies for lcm-spy
  // ARM_SETPOINT after every stream tick instead (desktop simulation with --can none, where the
  // robot program takes its setpoints from LCM: docs/roborio.md). Optional key, default off.
  bool setpoint_echo_full_rate = false;
  double trajectory_step_s = 0.01;  // ARM_TRAJECTORY sample step
  std::string log_level = "info";
  DeviceNumbers devices;
  ChannelNames channels;
};

}  // namespace cyber::config

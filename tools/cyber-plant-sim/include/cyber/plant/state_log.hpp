#pragma once
// The --log CSV of cyber-plant-sim: one row per ARM_STATE period (also while silent) and one at
// exit, so a test can read the trajectory the plant actually followed and its final error.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "cyber/planner.hpp"
#include "cyber/plant/mechanism_plant.hpp"
#include "cyber/plant/plant_simulation.hpp"

namespace cyber::plant {

struct StateLogRow {
  double t_s = 0.0;        // simulator time since start-up (monotonic), s
  std::int64_t utime = 0;  // wall clock, us: the ARM_STATE utime, comparable to candump's
  int joint_count = 0;     // N: the entries of the three arrays below that the row carries
  std::array<JointState, kMaxJoints> state{};
  std::array<std::optional<JointCommand>, kMaxJoints> command{};  // empty: neutral
  std::array<double, kMaxJoints> applied_volts{};
  bool heartbeat = false;        // the heartbeat is being sent
  bool robot_enabled = false;    // ... with the enabled and system-watchdog bits
  bool state_published = false;  // ARM_STATE went out this period (false while silent)
};

// The columns are named by the config's joints, NAME_UNIT with UNIT m (prismatic) or rad (revolute),
// the N joints' states first, then each joint's command and voltage; for the reference robot
// (elevator, arm):
// t_s,utime,elevator_m,elevator_mps,arm_rad,arm_radps,elevator_cmd_m,elevator_cmd_mps,
// elevator_ff_volts,elevator_volts,arm_cmd_rad,arm_cmd_radps,arm_ff_volts,arm_volts,
// heartbeat,robot_enabled,state_published  (command fields empty while neutral)
std::string stateLogHeader(const planner::JointChain& joints);
// The row's joint_count joints, in the header's order (a row of as many joints as the header's).
std::string stateLogRow(const StateLogRow& row);

}  // namespace cyber::plant

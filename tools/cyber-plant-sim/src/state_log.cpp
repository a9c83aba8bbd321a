#include "cyber/plant/state_log.hpp"

#include <cinttypes>
#include <cstdio>

#include "cyber/planner/types.hpp"

namespace cyber::plant {

namespace {

void append(std::string& out, const char* format, double value) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, format, value);
  out += ',';
  out += buffer;
}

void appendCommand(std::string& out, const std::optional<JointCommand>& command) {
  if (!command) {
    out += ",,,";
    return;
  }
  append(out, "%.6f", command->position);
  append(out, "%.6f", command->velocity);
  append(out, "%.4f", command->feedforward_volts);
}

}  // namespace

std::string stateLogHeader() {
  return "t_s,utime,elevator_m,elevator_mps,arm_rad,arm_radps,"
         "elevator_cmd_m,elevator_cmd_mps,elevator_ff_volts,elevator_volts,"
         "arm_cmd_rad,arm_cmd_radps,arm_ff_volts,arm_volts,"
         "heartbeat,robot_enabled,state_published";
}

std::string stateLogRow(const StateLogRow& row) {
  std::string out;
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6f,%" PRId64, row.t_s, row.utime);
  out += buffer;
  for (int joint : {planner::kElevator, planner::kArm}) {
    append(out, "%.6f", row.state[joint].position);
    append(out, "%.6f", row.state[joint].velocity);
  }
  for (int joint : {planner::kElevator, planner::kArm}) {
    appendCommand(out, row.command[joint]);
    append(out, "%.4f", row.applied_volts[joint]);
  }
  out += row.heartbeat ? ",1" : ",0";
  out += row.robot_enabled ? ",1" : ",0";
  out += row.state_published ? ",1" : ",0";
  return out;
}

}  // namespace cyber::plant

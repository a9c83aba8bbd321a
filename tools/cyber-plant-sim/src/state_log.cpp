#include "cyber/plant/state_log.hpp"

#include <fmt/format.h>

#include <iterator>

#include "cyber/planner/types.hpp"

namespace cyber::plant {

namespace {

void appendCommand(std::string& out, const std::optional<JointCommand>& command) {
  if (!command) {
    out += ",,,";
    return;
  }
  fmt::format_to(std::back_inserter(out), ",{:.6f},{:.6f},{:.4f}", command->position, command->velocity,
                 command->feedforward_volts);
}

}  // namespace

std::string stateLogHeader() {
  return "t_s,utime,elevator_m,elevator_mps,arm_rad,arm_radps,"
         "elevator_cmd_m,elevator_cmd_mps,elevator_ff_volts,elevator_volts,"
         "arm_cmd_rad,arm_cmd_radps,arm_ff_volts,arm_volts,"
         "heartbeat,robot_enabled,state_published";
}

std::string stateLogRow(const StateLogRow& row) {
  std::string out = fmt::format("{:.6f},{}", row.t_s, row.utime);
  for (int joint : {0, 1}) {
    fmt::format_to(std::back_inserter(out), ",{:.6f},{:.6f}", row.state[joint].position, row.state[joint].velocity);
  }
  for (int joint : {0, 1}) {
    appendCommand(out, row.command[joint]);
    fmt::format_to(std::back_inserter(out), ",{:.4f}", row.applied_volts[joint]);
  }
  out += row.heartbeat ? ",1" : ",0";
  out += row.robot_enabled ? ",1" : ",0";
  out += row.state_published ? ",1" : ",0";
  return out;
}

}  // namespace cyber::plant

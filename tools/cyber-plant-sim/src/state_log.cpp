#include "cyber/plant/state_log.hpp"

#include <fmt/format.h>

#include <iterator>

#include "cyber/planner.hpp"

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

std::string stateLogHeader(const planner::JointChain& joints) {
  std::string out = "t_s,utime";
  for (const planner::ChainJoint& joint : joints) {
    const char* unit = planner::unitName(joint.type);
    fmt::format_to(std::back_inserter(out), ",{0}_{1},{0}_{1}ps", joint.name, unit);
  }
  for (const planner::ChainJoint& joint : joints) {
    const char* unit = planner::unitName(joint.type);
    fmt::format_to(std::back_inserter(out), ",{0}_cmd_{1},{0}_cmd_{1}ps,{0}_ff_volts,{0}_volts", joint.name, unit);
  }
  return out + ",heartbeat,robot_enabled,state_published";
}

std::string stateLogRow(const StateLogRow& row) {
  std::string out = fmt::format("{:.6f},{}", row.t_s, row.utime);
  const auto joints = static_cast<std::size_t>(row.joint_count);
  for (std::size_t joint = 0; joint < joints; ++joint) {
    fmt::format_to(std::back_inserter(out), ",{:.6f},{:.6f}", row.state[joint].position, row.state[joint].velocity);
  }
  for (std::size_t joint = 0; joint < joints; ++joint) {
    appendCommand(out, row.command[joint]);
    fmt::format_to(std::back_inserter(out), ",{:.4f}", row.applied_volts[joint]);
  }
  out += row.heartbeat ? ",1" : ",0";
  out += row.robot_enabled ? ",1" : ",0";
  out += row.state_published ? ",1" : ",0";
  return out;
}

}  // namespace cyber::plant

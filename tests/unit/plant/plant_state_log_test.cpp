// The --log CSV format of cyber-plant-sim.

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cyber/planner.hpp"
#include "cyber/plant/state_log.hpp"

namespace cyber::plant {
namespace {

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream stream(line);
  for (std::string field; std::getline(stream, field, ',');) out.push_back(field);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

planner::JointChain chainOf(const std::vector<std::pair<std::string, planner::JointType>>& joints) {
  planner::JointChain chain;
  for (const auto& [name, type] : joints) {
    planner::ChainJoint joint;
    joint.name = name;
    joint.type = type;
    chain.push_back(joint);
  }
  return chain;
}

const planner::JointChain kReference =
    chainOf({{"elevator", planner::JointType::kPrismatic}, {"arm", planner::JointType::kRevolute}});

TEST(StateLog, ReferenceRobotHeader) {
  EXPECT_EQ(stateLogHeader(kReference),
            "t_s,utime,elevator_m,elevator_mps,arm_rad,arm_radps,"
            "elevator_cmd_m,elevator_cmd_mps,elevator_ff_volts,elevator_volts,"
            "arm_cmd_rad,arm_cmd_radps,arm_ff_volts,arm_volts,"
            "heartbeat,robot_enabled,state_published");
}

TEST(StateLog, ColumnsNamedByTheConfigJoints) {
  const auto joints = chainOf({{"shoulder", planner::JointType::kRevolute}, {"elbow", planner::JointType::kRevolute}});
  EXPECT_EQ(stateLogHeader(joints),
            "t_s,utime,shoulder_rad,shoulder_radps,elbow_rad,elbow_radps,"
            "shoulder_cmd_rad,shoulder_cmd_radps,shoulder_ff_volts,shoulder_volts,"
            "elbow_cmd_rad,elbow_cmd_radps,elbow_ff_volts,elbow_volts,"
            "heartbeat,robot_enabled,state_published");
}

TEST(StateLog, RowsMatchTheHeader) {
  StateLogRow row;
  row.t_s = 1.25;
  row.utime = 1700000000123456;
  row.joint_count = 2;
  row.state[0] = {0.5, -0.25};
  row.state[1] = {3.14159, 1.5};
  row.command[0] = JointCommand{0.501, -0.2, 0.42};
  row.applied_volts = {0.55, -1.25};
  row.heartbeat = true;
  row.robot_enabled = false;
  row.state_published = true;
  const auto header = fields(stateLogHeader(kReference));
  const auto values = fields(stateLogRow(row));
  ASSERT_EQ(header.size(), 17u);
  ASSERT_EQ(values.size(), header.size()) << stateLogRow(row);
  auto value = [&](const std::string& name) {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return values[i];
    }
    ADD_FAILURE() << "no column " << name;
    return std::string();
  };
  EXPECT_EQ(value("t_s"), "1.250000");
  EXPECT_EQ(value("utime"), "1700000000123456");
  EXPECT_EQ(value("elevator_m"), "0.500000");
  EXPECT_EQ(value("elevator_mps"), "-0.250000");
  EXPECT_EQ(value("arm_rad"), "3.141590");
  EXPECT_EQ(value("arm_radps"), "1.500000");
  EXPECT_EQ(value("elevator_cmd_m"), "0.501000");
  EXPECT_EQ(value("elevator_cmd_mps"), "-0.200000");
  EXPECT_EQ(value("elevator_ff_volts"), "0.4200");
  EXPECT_EQ(value("elevator_volts"), "0.5500");
  EXPECT_EQ(value("arm_cmd_rad"), "");  // neutral: no command
  EXPECT_EQ(value("arm_cmd_radps"), "");
  EXPECT_EQ(value("arm_ff_volts"), "");
  EXPECT_EQ(value("arm_volts"), "-1.2500");
  EXPECT_EQ(value("heartbeat"), "1");
  EXPECT_EQ(value("robot_enabled"), "0");
  EXPECT_EQ(value("state_published"), "1");
}

// One joint's columns per joint of the chain: a one-joint pivot and a three-joint elevator, pivot
// and wrist (config/intake-pivot.toml, config/reefscape-2025-elevator-pivot-wrist.toml).
TEST(StateLog, OneColumnGroupPerJointOfTheChain) {
  EXPECT_EQ(stateLogHeader(chainOf({{"pivot", planner::JointType::kRevolute}})),
            "t_s,utime,pivot_rad,pivot_radps,pivot_cmd_rad,pivot_cmd_radps,pivot_ff_volts,pivot_volts,"
            "heartbeat,robot_enabled,state_published");
  const auto three = chainOf({{"elevator", planner::JointType::kPrismatic},
                              {"pivot", planner::JointType::kRevolute},
                              {"wrist", planner::JointType::kRevolute}});
  EXPECT_EQ(stateLogHeader(three),
            "t_s,utime,elevator_m,elevator_mps,pivot_rad,pivot_radps,wrist_rad,wrist_radps,"
            "elevator_cmd_m,elevator_cmd_mps,elevator_ff_volts,elevator_volts,"
            "pivot_cmd_rad,pivot_cmd_radps,pivot_ff_volts,pivot_volts,"
            "wrist_cmd_rad,wrist_cmd_radps,wrist_ff_volts,wrist_volts,"
            "heartbeat,robot_enabled,state_published");

  StateLogRow row;
  row.t_s = 0.5;
  row.utime = 1;
  row.joint_count = 3;
  row.state = {JointState{0.1, 0.0}, JointState{1.5, 0.25}, JointState{-0.75, -2.0}};
  row.command[2] = JointCommand{-0.7, -1.9, 3.5};
  row.applied_volts = {0.0, 1.0, 4.25};
  EXPECT_EQ(stateLogRow(row),
            "0.500000,1,0.100000,0.000000,1.500000,0.250000,-0.750000,-2.000000,"
            ",,,0.0000,,,,1.0000,-0.700000,-1.900000,3.5000,4.2500,0,0,0");
  EXPECT_EQ(fields(stateLogRow(row)).size(), fields(stateLogHeader(three)).size());

  row.joint_count = 1;
  row.state[0] = {-0.72, 0.125};
  EXPECT_EQ(stateLogRow(row), "0.500000,1,-0.720000,0.125000,,,,0.0000,0,0,0");
}

}  // namespace
}  // namespace cyber::plant

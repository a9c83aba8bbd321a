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

planner::JointChain chain(const std::string& name0, planner::JointType type0, const std::string& name1,
                          planner::JointType type1) {
  planner::JointChain joints;
  joints[0].name = name0;
  joints[0].type = type0;
  joints[1].name = name1;
  joints[1].type = type1;
  return joints;
}

const planner::JointChain kReference =
    chain("elevator", planner::JointType::kPrismatic, "arm", planner::JointType::kRevolute);

TEST(StateLog, ReferenceRobotHeader) {
  EXPECT_EQ(stateLogHeader(kReference),
            "t_s,utime,elevator_m,elevator_mps,arm_rad,arm_radps,"
            "elevator_cmd_m,elevator_cmd_mps,elevator_ff_volts,elevator_volts,"
            "arm_cmd_rad,arm_cmd_radps,arm_ff_volts,arm_volts,"
            "heartbeat,robot_enabled,state_published");
}

TEST(StateLog, ColumnsNamedByTheConfigJoints) {
  const auto joints = chain("shoulder", planner::JointType::kRevolute, "elbow", planner::JointType::kRevolute);
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

}  // namespace
}  // namespace cyber::plant

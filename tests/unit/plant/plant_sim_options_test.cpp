// The command line of cyber-plant-sim.

#include <gtest/gtest.h>

#include "cyber/plant/sim_options.hpp"

namespace cyber::plant {
namespace {

SimArguments parse(const std::vector<std::string>& args) {
  const auto parsed = parseSimArguments(args);
  EXPECT_TRUE(parsed.ok()) << parsed.error().message;
  return parsed.ok() ? parsed.value() : SimArguments{};
}

std::string error(const std::vector<std::string>& args) {
  const auto parsed = parseSimArguments(args);
  EXPECT_FALSE(parsed.ok());
  return parsed.ok() ? "" : parsed.error().message;
}

TEST(SimOptions, DefaultsWithoutArguments) {
  const auto parsed = parse({});
  EXPECT_FALSE(parsed.help);
  const SimOptions& o = parsed.options;
  EXPECT_FALSE(o.config_path);
  EXPECT_FALSE(o.can_interface);
  EXPECT_FALSE(o.lcm_url);
  EXPECT_FALSE(o.initial_q);  // the config decides
  EXPECT_TRUE(o.pieces.empty());
  EXPECT_EQ(o.state_rate_hz, 100.0);
  EXPECT_TRUE(o.heartbeat);
  EXPECT_TRUE(o.faults.empty());
  EXPECT_FALSE(o.log_path);
  EXPECT_EQ(o.duration_s, 0.0);
  EXPECT_EQ(o.setpoint_timeout_s, 0.1);
  EXPECT_EQ(o.controller_bandwidth_radps, kDefaultControllerBandwidth_radps);
  for (const auto& gains : o.joint_gains) EXPECT_FALSE(gains);
  EXPECT_EQ(o.realtime_priority, 0);
  EXPECT_FALSE(o.control_path);
}

TEST(SimOptions, EveryOption) {
  const auto parsed = parse({"--config",
                             "robot.toml",
                             "--can",
                             "vcan0",
                             "--lcm-url",
                             "memq://",
                             "--initial",
                             "1.2,-0.5",
                             "--pieces",
                             "coral,algae",
                             "--state-rate",
                             "50",
                             "--no-heartbeat",
                             "--fault",
                             "heartbeat-stop@1.5",
                             "--fault",
                             "disable@motion+0.2",
                             "--log",
                             "out.csv",
                             "--duration",
                             "7.5",
                             "--setpoint-timeout",
                             "0.25",
                             "--bandwidth",
                             "60",
                             "--joint0-gains",
                             "200,2",
                             "--joint1-gains",
                             "40,0",
                             "--joint2-gains",
                             "15,0.5",
                             "--realtime",
                             "40",
                             "--control",
                             "ctl.fifo"});
  const SimOptions& o = parsed.options;
  EXPECT_EQ(o.config_path, "robot.toml");
  EXPECT_EQ(o.can_interface, "vcan0");
  EXPECT_EQ(o.lcm_url, "memq://");
  EXPECT_EQ(o.initial_q, (planner::JointVector{{1.2, -0.5}}));
  EXPECT_EQ(o.pieces, (std::vector<std::string>{"coral", "algae"}));
  EXPECT_EQ(o.state_rate_hz, 50.0);
  EXPECT_FALSE(o.heartbeat);
  ASSERT_EQ(o.faults.size(), 2u);
  EXPECT_EQ(o.faults[0], (FaultEvent{FaultKind::kHeartbeatStop, 0, 1.5}));
  EXPECT_EQ(o.faults[1], (FaultEvent{FaultKind::kBroadcastDisable, 1, 0.2}));
  EXPECT_EQ(o.log_path, "out.csv");
  EXPECT_EQ(o.duration_s, 7.5);
  EXPECT_EQ(o.setpoint_timeout_s, 0.25);
  EXPECT_EQ(o.controller_bandwidth_radps, 60.0);
  EXPECT_EQ(o.joint_gains[0]->kp_volts_per_unit, 200.0);
  EXPECT_EQ(o.joint_gains[0]->kd_volts_per_unit_per_s, 2.0);
  EXPECT_EQ(o.joint_gains[1]->kp_volts_per_unit, 40.0);
  EXPECT_EQ(o.joint_gains[1]->kd_volts_per_unit_per_s, 0.0);
  EXPECT_EQ(o.joint_gains[2]->kp_volts_per_unit, 15.0);
  EXPECT_EQ(o.joint_gains[2]->kd_volts_per_unit_per_s, 0.5);
  EXPECT_EQ(o.realtime_priority, 40);
  EXPECT_EQ(o.control_path, "ctl.fifo");
}

TEST(SimOptions, Help) {
  EXPECT_TRUE(parse({"--help"}).help);
  EXPECT_TRUE(parse({"--can", "vcan0", "-h"}).help);
  EXPECT_NE(simUsage().find("--fault KIND@WHEN"), std::string_view::npos);
}

TEST(SimOptions, BadUsageNamesTheProblem) {
  const std::vector<std::vector<std::string>> bad = {
      {"--bogus"},
      {"vcan0"},
      {"--can"},
      {"--can", ""},
      {"--initial", "1.0,2.0,3.0,4.0"},  // more joints than any chain has
      {"--initial", "a,b"},
      {"--initial", "1.0,nan"},
      {"--initial", "inf"},
      {"--initial", "1.0,"},
      {"--initial", ",1.0"},
      {"--initial", "1.0,,2.0"},
      {"--state-rate", "0"},
      {"--state-rate", "2000"},
      {"--state-rate", "fast"},
      {"--fault", "boom@1"},
      {"--fault"},
      {"--duration", "-1"},
      {"--setpoint-timeout", "0"},
      {"--joint0-gains", "1"},
      {"--joint1-gains", "-1,0"},
      {"--joint2-gains", "1,0,0"},
      {"--joint3-gains", "1,0"},
      {"--elevator-gains", "1,0"},
      {"--bandwidth", "0"},
      {"--bandwidth", "-5"},
      {"--bandwidth", "fast"},
      {"--log"},
      {"--control"},
      {"--realtime", "0"},
      {"--realtime", "100"},
      {"--realtime", "1.5"},
      {"--initial="},
      {"--initial=1.0,2.0x"},
      {"--pieces", "coral,"},
  };
  for (const auto& args : bad) {
    const std::string message = error(args);
    const std::string name = args.front().substr(0, args.front().find('='));
    EXPECT_NE(message.find(name), std::string::npos) << message;
  }
}

// One value per joint: whether there are as many as the config has joints is checked once it is
// loaded (plant_sim_tool_test), so a chain of one, two or three joints parses here.
TEST(SimOptions, InitialTakesOneValuePerJoint) {
  EXPECT_EQ(parse({"--initial", "1.9"}).options.initial_q, planner::JointVector{{1.9}});
  EXPECT_EQ(parse({"--initial", "-0.72"}).options.initial_q->size(), 1);
  EXPECT_EQ(parse({"--initial", "0.05,1.5708,0"}).options.initial_q, (planner::JointVector{{0.05, 1.5708, 0.0}}));
  EXPECT_EQ(parse({"--initial=0.5,-1e-3"}).options.initial_q, (planner::JointVector{{0.5, -1e-3}}));
}

TEST(SimOptions, BothSpellingsOfAValueMeanTheSame) {
  for (const auto& args : {std::vector<std::string>{"--initial", "-0.2,1", "--can", "vcan1", "--fault", "exit@2"},
                           std::vector<std::string>{"--initial=-0.2,1", "--can=vcan1", "--fault=exit@2"}}) {
    const SimOptions o = parse(args).options;
    EXPECT_EQ(o.initial_q, (planner::JointVector{{-0.2, 1.0}}));
    EXPECT_EQ(o.can_interface, "vcan1");
    ASSERT_EQ(o.faults.size(), 1u);
    EXPECT_EQ(o.faults[0].kind, FaultKind::kExit);
  }
}

}  // namespace
}  // namespace cyber::plant

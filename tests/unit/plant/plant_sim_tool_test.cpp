// The command-line contract of the cyber-plant-sim binary: help, bad usage and bad config exit 2,
// a CAN interface that cannot be opened exits 1 with a message. (Its behaviour on a bus is tested
// by the HIL tests on vcan.)

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include "tool_run.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace {

using cyber::test::readFile;
using cyber::test::ToolRun;

std::string tempPath(const std::string& name) {
  return ::testing::TempDir() + "cyber_plant_sim_" + std::to_string(::getpid()) + "_" + name;
}

ToolRun runTool(const std::string& args) { return cyber::test::runTool(CYBER_PLANT_SIM, args); }

TEST(PlantSimTool, HelpExitsZero) {
  const ToolRun run = runTool("--help");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("usage: cyber-plant-sim"), std::string::npos);
  EXPECT_NE(run.out.find("--initial Q0[,Q1[,Q2]]"), std::string::npos);
  EXPECT_NE(run.out.find("--joint2-gains KP,KD"), std::string::npos);
}

TEST(PlantSimTool, BadUsageExitsTwoWithTheUsage) {
  const ToolRun run = runTool("--fault explode@1");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("unknown fault 'explode'"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("usage:"), std::string::npos);
  EXPECT_TRUE(run.out.empty());
}

TEST(PlantSimTool, InitialPoseOutsideTheRangeExitsTwo) {
  const ToolRun run = runTool("--initial 2.5,1.0 --can nosuchcan0");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("outside the joint ranges"), std::string::npos) << run.err;
}

std::string shippedConfig(const std::string& name) {
  return std::string(CYBER_SOURCE_DIR) + "/config/" + name + ".toml";
}

// --initial takes one value per joint of the config, named in the refusal.
TEST(PlantSimTool, InitialPoseWithoutOneValuePerJointExitsTwo) {
  ToolRun run = runTool("--initial 0.5 --can nosuchcan0");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("reefscape-2025 has 2 joints (elevator, arm), one value each"), std::string::npos) << run.err;
  run = runTool("--config " + shippedConfig("intake-pivot") + " --initial 0.5,1.0 --can nosuchcan0");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("intake-pivot has 1 joint (pivot), one value each"), std::string::npos) << run.err;
  run = runTool("--config " + shippedConfig("reefscape-2025-elevator-pivot-wrist") +
                " --initial 0.5,1.0 --can nosuchcan0");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("has 3 joints (elevator, pivot, wrist)"), std::string::npos) << run.err;
}

TEST(PlantSimTool, GainsForAJointTheConfigLacksExitTwo) {
  ToolRun run = runTool("--joint2-gains 10,0 --can nosuchcan0");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--joint2-gains: reefscape-2025 has 2 joints"), std::string::npos) << run.err;
  run = runTool("--config " + shippedConfig("intake-pivot") + " --joint1-gains 10,0 --can nosuchcan0");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--joint1-gains: intake-pivot has 1 joint (pivot)"), std::string::npos) << run.err;
}

// The one- and three-joint robots pass every check of their options and config (initial pose,
// gains, pieces, one device per joint) and get as far as opening the CAN interface.
TEST(PlantSimTool, ChainsOfOneAndThreeJointsGetToTheBus) {
  for (const std::string& args :
       {"--config " + shippedConfig("intake-pivot") + " --pieces coral",
        "--config " + shippedConfig("intake-pivot") + " --initial -0.72 --joint0-gains 30,0.5",
        "--config " + shippedConfig("reefscape-2025-elevator-pivot-wrist"),
        "--config " + shippedConfig("reefscape-2025-elevator-pivot-wrist") +
            " --initial 0.05,1.5708,0 --joint2-gains 20,0 --pieces coral"}) {
    const ToolRun run = runTool(args + " --can nosuchcan0 --duration 0.1");
    EXPECT_EQ(run.exit_code, 1) << args << "\n" << run.err;
    EXPECT_NE(run.err.find("nosuchcan0"), std::string::npos) << args << "\n" << run.err;
  }
}

TEST(PlantSimTool, InvalidConfigExitsTwoNamingTheKey) {
  const std::string path = tempPath("bad.toml");
  std::ofstream(path) << "name = \"x\"\n";
  const ToolRun run = runTool("--config " + path + " --can nosuchcan0");
  std::remove(path.c_str());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("cyber-plant-sim: "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(path), std::string::npos) << run.err;
}

// Without CAN in the kernel (our machines) or without that interface (a laptop), open fails.
TEST(PlantSimTool, UnopenableCanInterfaceExitsOne) {
  const ToolRun run = runTool("--can nosuchcan0 --duration 0.1");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("nosuchcan0"), std::string::npos) << run.err;
}

}  // namespace

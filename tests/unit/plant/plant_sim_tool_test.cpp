// The command-line contract of the cyber-plant-sim binary: help, bad usage and bad config exit 2,
// a CAN interface that cannot be opened exits 1 with a message. (Its behaviour on a bus is tested
// by the HIL tests on vcan.)

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace {

struct ToolRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

std::string tempPath(const std::string& name) {
  return ::testing::TempDir() + "cyber_plant_sim_" + std::to_string(::getpid()) + "_" + name;
}

std::string readFile(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

ToolRun runTool(const std::string& args) {
  const std::string err_path = tempPath("stderr.txt");
  const std::string command = std::string(CYBER_PLANT_SIM) + " " + args + " 2>" + err_path;
  ToolRun run;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return run;
  char buffer[4096];
  size_t got;
  while ((got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) run.out.append(buffer, got);
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.err = readFile(err_path);
  std::remove(err_path.c_str());
  return run;
}

TEST(PlantSimTool, HelpExitsZero) {
  const ToolRun run = runTool("--help");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("usage: cyber-plant-sim"), std::string::npos);
  EXPECT_NE(run.out.find("--initial T,THETA"), std::string::npos);
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

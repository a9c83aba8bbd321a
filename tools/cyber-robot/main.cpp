// cyber-robot check: the first command a team runs on its robot description (docs/configuration.md,
// "Checking a robot"). Exit: 0 no error, 1 an error (or a description that does not load), 2 bad
// usage.

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cyber/cli/usage_exit.hpp"
#include "cyber/config/load_config.hpp"
#include "cyber/plot/world_view.hpp"
#include "robot_arguments.hpp"
#include "robot_check.hpp"
#include "robot_report.hpp"

namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "cyber-robot: %s\n", message.c_str());
  return 1;
}

// FILE.png for the first pose set, FILE-SET.png for each other one.
std::string pngPath(const std::string& path, size_t set_index, const std::string& set_name) {
  if (set_index == 0) return path;
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "-" + set_name + p.extension().string())).string();
}

int drawPoses(const cyber::config::Config& config, const std::string& path) {
  using namespace cyber;
  for (size_t i = 0; i < config.poses.size(); ++i) {
    const config::PoseSet& set = config.poses[i];
    std::vector<plot::NamedJointPose> poses;
    for (const config::NamedPose& p : set.poses) poses.push_back({p.name, p.q});
    const std::string title = config.robot.name + ": [poses." + set.name + "] over " + config.robot.scenes.front().name;
    const auto written =
        plot::renderConfigPreviewPng(config.robot, 0, set.pieces, poses, title, pngPath(path, i, set.name));
    if (!written) return fail(written.error().message);
    std::printf("wrote %s\n", pngPath(path, i, set.name).c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace cyber;
  const auto parsed = tools::parseRobotArguments(std::vector<std::string>(argv + 1, argv + argc));
  if (const auto status = cli::exitBeforeWork(parsed, {"cyber-robot", tools::robotUsage()})) return *status;
  const tools::RobotArguments& args = parsed.value();
  config::Config config;
  try {
    config = config::loadConfigFile(args.config_path);
  } catch (const config::ConfigError& e) {
    return fail(e.what());
  }
  const auto planner = planner::MotionPlanner::create(config.robot, planner::GridSelection{0, 0.0});
  if (!planner) return fail(planner.error().message);
  tools::RobotCheck check;
  check.poses = tools::checkPoseClearances(config);
  check.reach = tools::checkReach(config, planner.value());
  const planner::HeldPieces heaviest = tools::heaviestPieces(config.robot);
  check.heaviest_set = config.robot.pieceSetName(heaviest);
  check.drives = tools::checkDrives(config.robot, heaviest);
  std::fputs(tools::robotReportText(config, check).c_str(), stdout);
  if (!args.png_path.empty()) {
    if (const int status = drawPoses(config, args.png_path); status != 0) return status;
  }
  return check.count(tools::Severity::kError) > 0 ? 1 : 0;
}

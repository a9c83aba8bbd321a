// cyber-plot: draws a planned trajectory from a cyber-plan CSV or an LCM log (ARM_TRAJECTORY) as
// the same picture cyber-plan --plot makes. Exit: 0 written, 2 bad input.

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "cyber/config/load_config.hpp"
#include "trajectory_sources.hpp"

namespace {

const char* kUsage =
    "usage: cyber-plot [--config FILE] (--csv FILE | --lcm-log FILE [--channel NAME] [--request-id N])\n"
    "                  [--coral] [--algae] [--scene NAME] --out FILE.png\n"
    "Draws the C-space (obstacle region of the held pieces) with the path, and position, velocity,\n"
    "voltage and current against time with the limits, like cyber-plan --plot.\n"
    "  --csv FILE        a trajectory written by cyber-plan --csv\n"
    "  --lcm-log FILE    an lcm-logger log; plots its last ARM_TRAJECTORY (or the one of --request-id)\n"
    "  --config FILE     robot description (default: the embedded config/reefscape-2025.toml)\n";

int fail(const std::string& message) {
  std::fprintf(stderr, "cyber-plot: %s\n", message.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace cyber;
  std::string config_path, csv, log, channel, scene_name, out;
  std::optional<int64_t> request_id;
  planner::HeldPieces pieces;
  const std::vector<std::string> args(argv + 1, argv + argc);
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string* into) {
      if (i + 1 >= args.size()) return false;
      *into = args[++i];
      return true;
    };
    std::string text;
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (a == "--coral") {
      pieces.coral = true;
    } else if (a == "--algae") {
      pieces.algae = true;
    } else if ((a == "--config" && value(&config_path)) || (a == "--csv" && value(&csv)) ||
               (a == "--lcm-log" && value(&log)) || (a == "--channel" && value(&channel)) ||
               (a == "--scene" && value(&scene_name)) || (a == "--out" && value(&out))) {
    } else if (a == "--request-id" && value(&text)) {
      char* end = nullptr;
      request_id = std::strtoll(text.c_str(), &end, 10);
      if (end == text.c_str() || *end != '\0') return fail("--request-id expects an integer, got \"" + text + "\"");
    } else {
      return fail("unknown or incomplete argument \"" + a + "\" (see --help)");
    }
  }
  if (out.empty()) return fail("missing --out FILE.png");
  if (csv.empty() == log.empty()) return fail("give exactly one of --csv and --lcm-log");

  config::Config config;
  try {
    config = config_path.empty() ? config::loadEmbeddedDefaultConfig() : config::loadConfigFile(config_path);
  } catch (const config::ConfigError& e) {
    return fail(e.what());
  }
  const planner::RobotModel& robot = config.robot;
  const int scene = scene_name.empty() ? 0 : robot.sceneIndex(scene_name);
  if (scene < 0) return fail("unknown scene \"" + scene_name + "\"");
  if (channel.empty()) channel = config.daemon.channels.trajectory;

  plot::TrajectoryPlotData data;
  std::string error;
  const bool ok = csv.empty() ? tools::readTrajectoryFromLog(log, channel, request_id, robot, data, &error)
                              : tools::readPlanCsv(csv, data, &error);
  if (!ok) return fail(error);
  if (data.title.empty()) data.title = "trajectory " + csv;
  if (pieces.coral) data.title += " +coral";
  if (pieces.algae) data.title += " +algae";
  data.cspace = plot::sampleCSpace(robot, scene, pieces);
  for (int j = 0; j < 2; ++j) {
    data.voltage_limit_volts[j] = robot.drive(j).voltage_limit_volts;
    data.current_limit_amps[j] = robot.drive(j).current_limit_amps;
  }
  if (!plot::renderTrajectoryPng(data, out, &error)) return fail(error);
  return 0;
}

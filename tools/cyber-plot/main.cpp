// cyber-plot: draws a planned trajectory from a cyber-plan CSV or an LCM log (ARM_TRAJECTORY) as
// the same picture cyber-plan --plot makes; with --world the robot in its scene (a pose, or a
// move as a filmstrip and an APNG animation); with only --config a preview of the description
// (docs/configuration.md). Exit: 0 written, 2 bad input.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "cyber/config/load_config.hpp"
#include "cyber/plot/world_view.hpp"
#include "trajectory_sources.hpp"

namespace {

const char* kUsage =
    "usage: cyber-plot [--config FILE] (--csv FILE | --lcm-log FILE [--channel NAME] [--request-id N])\n"
    "                  [--coral] [--algae] [--scene NAME] --out FILE.png\n"
    "       cyber-plot --world [--config FILE] (--at ELEVATOR_M,ARM_RAD | --csv FILE | --lcm-log FILE ...)\n"
    "                  [--frames N] [--animation FILE.png] [--coral] [--algae] [--scene NAME] --out FILE.png\n"
    "       cyber-plot --config FILE [--coral] [--algae] [--scene NAME] --out FILE.png\n"
    "Draws the C-space (obstacle region of the held pieces) with the path, and position, velocity,\n"
    "voltage and current against time with the limits, like cyber-plan --plot.\n"
    "  --csv FILE        a trajectory written by cyber-plan --csv\n"
    "  --lcm-log FILE    an lcm-logger log; plots its last ARM_TRAJECTORY (or the one of --request-id)\n"
    "  --config FILE     robot description (default: the embedded config/reefscape-2025.toml); alone,\n"
    "                    previews it: the robot at its named poses ([poses.*] of the held pieces) over\n"
    "                    the obstacles, and the C-space map with those poses\n"
    "  --world           the side view of the scene with the robot: at --at, or for a trajectory a\n"
    "                    filmstrip of --frames poses (default 6) plus the pose of smallest clearance\n"
    "  --animation FILE  with --world and a trajectory: also an animated PNG (APNG, 25 frames/s)\n";

int fail(const std::string& message) {
  std::fprintf(stderr, "cyber-plot: %s\n", message.c_str());
  return 2;
}

// The robot at the named poses of its held-piece set, or at a few poses spread over the joint
// ranges when the description names none.
int previewConfig(const cyber::config::Config& config, int scene, cyber::planner::HeldPieces pieces, const std::string& source,
                  const std::string& out) {
  using namespace cyber;
  const planner::RobotModel& robot = config.robot;
  std::vector<plot::NamedJointPose> poses;
  std::string set_name = "none";
  for (const config::PoseSet& set : config.poses) {
    if (set.pieces.coral == pieces.coral && set.pieces.algae == pieces.algae) {
      set_name = set.name;
      for (const config::NamedPose& p : set.poses) poses.push_back({p.name, p.q});
    }
  }
  const bool named = !poses.empty();
  if (!named) {
    const planner::JointRange e = robot.elevator_range_m, a = robot.arm_range_rad;
    for (double f : {0.1, 0.5, 0.9}) {
      const planner::JointVector q(e.min + f * (e.max - e.min), a.min + f * (a.max - a.min));
      char name[48];
      std::snprintf(name, sizeof name, "%.2f m, %.2f rad", q[0], q[1]);
      poses.push_back({name, q});
    }
  }
  const std::string which = named ? "poses of [poses." + set_name + "]" : "no [poses] for these pieces: poses across the ranges";
  const std::string title = robot.name + " (" + source + "): " + which + ", scene " + robot.scenes[static_cast<size_t>(scene)].name;
  std::string error;
  if (!plot::renderConfigPreviewPng(robot, scene, pieces, poses, title, out, &error)) return fail(error);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace cyber;
  std::string config_path, csv, log, channel, scene_name, out, animation, at_text;
  std::optional<int64_t> request_id;
  bool world = false;
  int frames = 6;
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
    } else if (a == "--world") {
      world = true;
    } else if (a == "--frames" && value(&text)) {
      char* end = nullptr;
      frames = static_cast<int>(std::strtol(text.c_str(), &end, 10));
      if (end == text.c_str() || *end != '\0' || frames < 2 || frames > 20) return fail("--frames expects 2 to 20, got \"" + text + "\"");
    } else if (a == "--coral") {
      pieces.coral = true;
    } else if (a == "--algae") {
      pieces.algae = true;
    } else if ((a == "--config" && value(&config_path)) || (a == "--csv" && value(&csv)) ||
               (a == "--lcm-log" && value(&log)) || (a == "--channel" && value(&channel)) ||
               (a == "--scene" && value(&scene_name)) || (a == "--out" && value(&out)) ||
               (a == "--animation" && value(&animation)) || (a == "--at" && value(&at_text))) {
    } else if (a == "--request-id" && value(&text)) {
      char* end = nullptr;
      request_id = std::strtoll(text.c_str(), &end, 10);
      if (end == text.c_str() || *end != '\0') return fail("--request-id expects an integer, got \"" + text + "\"");
    } else {
      return fail("unknown or incomplete argument \"" + a + "\" (see --help)");
    }
  }
  if (out.empty()) return fail("missing --out FILE.png");
  const bool preview = !world && csv.empty() && log.empty() && !config_path.empty();
  if (!world && (!animation.empty() || !at_text.empty())) return fail("--animation and --at need --world");
  const int sources = (csv.empty() ? 0 : 1) + (log.empty() ? 0 : 1) + (at_text.empty() ? 0 : 1);
  if (!preview && (world ? sources != 1 : sources != 1 || !at_text.empty())) {
    return fail(world ? "give exactly one of --at, --csv and --lcm-log" : "give exactly one of --csv and --lcm-log");
  }
  if (!at_text.empty() && !animation.empty()) return fail("--animation needs a trajectory (--csv or --lcm-log), not --at");

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
  const std::string pieces_label = std::string(pieces.coral ? " +coral" : "") + (pieces.algae ? " +algae" : "");
  const std::string scene_label = " (scene " + robot.scenes[static_cast<size_t>(scene)].name + ")";
  std::string error;

  if (preview) return previewConfig(config, scene, pieces, config_path, out);
  if (!at_text.empty()) {
    double e = 0, a = 0;
    char tail = 0;
    if (std::sscanf(at_text.c_str(), "%lf,%lf%c", &e, &a, &tail) != 2 || !std::isfinite(e) || !std::isfinite(a)) {
      return fail("--at expects ELEVATOR_M,ARM_RAD, got \"" + at_text + "\"");
    }
    const planner::JointVector q(e, a);
    if (!robot.withinLimits(q)) return fail("--at " + at_text + " is outside the joint ranges");
    char title[96];
    std::snprintf(title, sizeof title, "%s at %.3f m, %.3f rad", robot.name.c_str(), e, a);
    if (!plot::renderWorldPng(robot, scene, pieces, q, title + pieces_label + scene_label, out, &error)) return fail(error);
    return 0;
  }

  plot::TrajectoryPlotData data;
  const bool ok = csv.empty() ? tools::readTrajectoryFromLog(log, channel, request_id, robot, data, &error)
                              : tools::readPlanCsv(csv, data, &error);
  if (!ok) return fail(error);
  if (data.title.empty()) data.title = "trajectory " + csv;
  data.title += pieces_label;
  if (world) {
    const plot::Move move = plot::moveOf(data);
    if (!plot::renderFilmstripPng(robot, scene, pieces, move, frames, data.title + scene_label, out, &error)) return fail(error);
    if (!animation.empty() && !plot::renderAnimationApng(robot, scene, pieces, move, 25, data.title, animation, &error)) {
      return fail(error);
    }
    return 0;
  }
  data.cspace = plot::sampleCSpace(robot, scene, pieces);
  for (int j = 0; j < 2; ++j) {
    data.voltage_limit_volts[j] = robot.drive(j).voltage_limit_volts;
    data.current_limit_amps[j] = robot.drive(j).current_limit_amps;
  }
  if (!plot::renderTrajectoryPng(data, out, &error)) return fail(error);
  return 0;
}

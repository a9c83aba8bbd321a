// cyber-plot: draws a planned trajectory from a cyber-plan CSV or an LCM log (ARM_TRAJECTORY) as
// the same picture cyber-plan --plot makes; with --world the robot in its scene (a pose, or a
// move as a filmstrip and an APNG animation); with only --config a preview of the description
// (docs/configuration.md). Exit: 0 written, 2 bad input.

#include <fmt/format.h>

#include <cstdio>
#include <string>
#include <vector>

#include "cyber/cli/usage_exit.hpp"
#include "cyber/config/load_config.hpp"
#include "cyber/plot/world_view.hpp"
#include "plot_arguments.hpp"
#include "robot_check.hpp"
#include "trajectory_sources.hpp"

namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "cyber-plot: %s\n", message.c_str());
  return 2;
}

// 0 when the picture is written, else fail's.
int exitOf(const cyber::Result<cyber::Done, cyber::plot::PlotStatus>& written) {
  return written ? 0 : fail(written.error().message);
}

// A named pose drawn in a scene where it is closer than the clearance is drawn all the same (a
// pose may be meant for one field element only), with a warning (cyber-robot check's rule).
void warnCloserThanTheClearance(const cyber::config::Config& config, int scene, const std::string& set_name) {
  const std::string& scene_name = config.robot.scenes[static_cast<size_t>(scene)].name;
  for (const cyber::tools::PoseClearance& p : cyber::tools::checkPoseClearances(config)) {
    if (p.pose_set != set_name || p.scene != scene_name || p.clearance_m >= config.robot.clearance_m) continue;
    std::fprintf(
        stderr,
        "cyber-plot: warning: pose [poses.%s] %s is %.3f m from %s in scene %s, closer than the clearance %.3f m\n",
        p.pose_set.c_str(), p.pose.c_str(), p.clearance_m, p.closest.c_str(), scene_name.c_str(),
        config.robot.clearance_m);
  }
}

// "0.20 m, 1.57 rad": a pose by its values and units, chain order, `decimals` after the point.
std::string poseText(const cyber::planner::RobotModel& robot, const cyber::planner::JointVector& q, int decimals = 2) {
  std::string out;
  for (int j = 0; j < robot.jointCount(); ++j) {
    out +=
        fmt::format("{}{:.{}f} {}", j == 0 ? "" : ", ", q[j], decimals, cyber::planner::unitName(robot.joints[j].type));
  }
  return out;
}

// The robot at the named poses of its held-piece set, or at a few poses spread over the joint
// ranges when the description names none.
int previewConfig(const cyber::config::Config& config, int scene, cyber::planner::HeldPieces pieces,
                  const std::string& source, const std::string& out) {
  using namespace cyber;
  const planner::RobotModel& robot = config.robot;
  std::vector<plot::NamedJointPose> poses;
  std::string set_name = "none";
  for (const config::PoseSet& set : config.poses) {
    if (set.pieces == pieces) {
      set_name = set.name;
      for (const config::NamedPose& p : set.poses) poses.push_back({p.name, p.q});
    }
  }
  const bool named = !poses.empty();
  if (!named) {
    for (double f : {0.1, 0.5, 0.9}) {
      planner::JointVector q(robot.jointCount());
      for (int j = 0; j < robot.jointCount(); ++j)
        q[j] = robot.range(j).min + f * (robot.range(j).max - robot.range(j).min);
      poses.push_back({poseText(robot, q), q});
    }
  }
  warnCloserThanTheClearance(config, scene, set_name);
  const std::string which =
      named ? "poses of [poses." + set_name + "]" : "no [poses] for these pieces: poses across the ranges";
  const std::string title =
      robot.name + " (" + source + "): " + which + ", scene " + robot.scenes[static_cast<size_t>(scene)].name;
  return exitOf(plot::renderConfigPreviewPng(robot, scene, pieces, poses, title, out));
}

}  // namespace

int main(int argc, char** argv) {
  using namespace cyber;
  const auto parsed = tools::parsePlotArguments(std::vector<std::string>(argv + 1, argv + argc));
  if (const auto status = cli::exitBeforeWork(parsed, {"cyber-plot", tools::plotUsage()})) return *status;
  const tools::PlotArguments& args = parsed.value();
  const std::string& csv = args.csv_path;
  const std::string& out = args.out_path;

  config::Config config;
  try {
    config = args.config_path.empty() ? config::loadEmbeddedDefaultConfig() : config::loadConfigFile(args.config_path);
  } catch (const config::ConfigError& e) {
    return fail(e.what());
  }
  const planner::RobotModel& robot = config.robot;
  const int scene = args.scene.empty() ? 0 : robot.sceneIndex(args.scene);
  if (scene < 0) return fail("unknown scene \"" + args.scene + "\"");
  const auto held = robot.piecesNamed(args.pieces);
  if (!held) return fail("--pieces: " + held.error().message);
  const planner::HeldPieces pieces = held.value();
  const std::string channel = args.channel.empty() ? config.daemon.channels.trajectory : args.channel;
  const std::string pieces_label = pieces.empty() ? "" : " +" + robot.pieceSetName(pieces);
  const std::string scene_label = " (scene " + robot.scenes[static_cast<size_t>(scene)].name + ")";

  if (args.preview()) return previewConfig(config, scene, pieces, args.config_path, out);
  if (args.at) {
    const planner::JointVector q = *args.at;
    if (q.size() != robot.jointCount()) {
      return fail(fmt::format("--at {} has {} values, {} has {} joints (one position per joint, chain order)",
                              args.at_text, q.size(), robot.name, robot.jointCount()));
    }
    if (!robot.withinLimits(q)) return fail("--at " + args.at_text + " is outside the joint ranges");
    const std::string title = robot.name + " at " + poseText(robot, q, 3) + pieces_label + scene_label;
    return exitOf(plot::renderWorldPng(robot, scene, pieces, q, title, out));
  }

  auto source = csv.empty() ? tools::readTrajectoryFromLog(args.log_path, channel, args.request_id, robot)
                            : tools::readPlanCsv(csv, robot.joints);
  if (!source) return fail(source.error().message);
  plot::TrajectoryPlotData& data = source.value();
  if (data.title.empty()) data.title = "trajectory " + csv;
  data.title += pieces_label;
  if (args.world) {
    const plot::Move move = plot::moveOf(data);
    const auto strip = plot::renderFilmstripPng(robot, scene, pieces, move, args.frames, data.title + scene_label, out);
    if (!strip || args.animation_path.empty()) return exitOf(strip);
    return exitOf(plot::renderAnimationApng(robot, scene, pieces, move, 25, data.title, args.animation_path));
  }
  plot::addRobotView(data, robot, scene, pieces);
  return exitOf(plot::renderTrajectoryPng(data, out));
}

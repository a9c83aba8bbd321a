// cyber-plan: plans one move with the planner core and writes what design.md promises.
// Exit status: 0 planned, 2 bad input, 3 no feasible motion; a one-line reason on stderr.

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cyber/cli/usage_exit.hpp"
#include "cyber/config/load_config.hpp"
#include "cyber/planner.hpp"
#include "plan_arguments.hpp"
#include "plan_output.hpp"

namespace {

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "cyber-plan: %s\n", message.c_str());
  return code;
}

// The pose in its joints' units (m or rad), after its name when it was given by name.
std::string poseText(const cyber::planner::RobotModel& robot, const cyber::tools::PoseArgument& given,
                     const cyber::planner::JointVector& q) {
  std::string text = given.name.empty() ? "(" : given.name + " (";
  for (int j = 0; j < robot.jointCount(); ++j) {
    text += fmt::format("{}{:.3f} {}", j == 0 ? "" : ", ", q[j], cyber::planner::unitName(robot.joints[j].type));
  }
  return text + ")";
}

// The grid cache's folder (docs/design.md, "The grid cache"): $XDG_CACHE_HOME/cyber-planner, or
// ~/.cache/cyber-planner (the XDG default); none without a home. A folder that cannot be written
// only costs the time: the planner builds its grids as without one.
std::optional<std::filesystem::path> gridCacheDir() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  // The XDG specification ignores a relative path.
  if (xdg != nullptr && xdg[0] == '/') return std::filesystem::path(xdg) / "cyber-planner";
  const char* home = std::getenv("HOME");
  if (home == nullptr || home[0] != '/') return std::nullopt;
  return std::filesystem::path(home) / ".cache" / "cyber-planner";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace cyber;
  const auto args = tools::parsePlanArguments(std::vector<std::string>(argv + 1, argv + argc));
  if (const auto status = cli::exitBeforeWork(args, {"cyber-plan", tools::planUsage()})) return *status;

  config::Config config;
  try {
    config =
        args->config_path.empty() ? config::loadEmbeddedDefaultConfig() : config::loadConfigFile(args->config_path);
  } catch (const config::ConfigError& e) {
    return fail(2, e.what());
  }
  const planner::RobotModel& robot = config.robot;
  int scene = 0;
  if (!args->scene.empty()) {
    scene = robot.sceneIndex(args->scene);
    if (scene < 0) return fail(2, "unknown scene \"" + args->scene + "\"");
  }

  const auto pieces = robot.piecesNamed(args->pieces);
  if (!pieces) return fail(2, "--pieces: " + pieces.error().message);
  // A named pose is one of the held set's (docs/configuration.md, "Named poses").
  const auto from = tools::resolvePose(args->from, config, pieces.value());
  if (!from) return fail(2, "--from: " + from.error().message);
  const auto to = tools::resolvePose(args->to, config, pieces.value());
  if (!to) return fail(2, "--to: " + to.error().message);

  // Only the grids this move needs: the start-up is most of a cyber-plan run.
  auto planner = planner::MotionPlanner::create(robot, {scene, args->scene_offset_m}, gridCacheDir());
  if (!planner) return fail(planner::exitCodeOf(planner.status()), planner.error().message);

  if (args->from_velocity.size() != 0 && args->from_velocity.size() != robot.jointCount()) {
    return fail(2, fmt::format("--from-velocity: expects {} values, one per joint, got {}", robot.jointCount(),
                               args->from_velocity.size()));
  }

  planner::PlanRequest request;
  request.start = from.value();
  request.goal = to.value();
  request.start_velocity = args->from_velocity;
  request.pieces = pieces.value();
  request.scene = scene;
  request.scene_offset_m = args->scene_offset_m;
  const auto plan = planner.value().plan(request);
  if (!plan) {
    return fail(planner::exitCodeOf(plan.status()),
                std::string(planner::toString(plan.status())) + ": " + plan.error().message);
  }

  if (!args->csv_path.empty()) {
    const planner::Trajectory& trajectory = *plan.value().trajectory;
    double step_s = args->csv_step_s.value_or(tools::kCsvStepS);
    if (!args->csv_step_s) {
      const tools::CsvSpacing spacing = tools::csvSpacingFor(trajectory, robot.planner.motion);
      step_s = spacing.step_s;
      if (spacing.reason != tools::FinerCsvReason::kNone)
        std::fprintf(stderr, "%s\n", tools::finerCsvMessage(spacing).c_str());
    }
    if (const auto written = tools::writeTrajectoryCsv(trajectory, robot.joints, args->csv_path, step_s); !written)
      return fail(2, written.error().message);
  }
  if (!args->plot_path.empty()) {
    const std::string title = "cyber-plan " + poseText(robot, args->from, from.value()) + " -> " +
                              poseText(robot, args->to, to.value()) +
                              (pieces->empty() ? "" : " +" + robot.pieceSetName(pieces.value()));
    const auto drawn = plot::renderTrajectoryPng(tools::plotDataOf(plan.value(), robot, scene, pieces.value(), title),
                                                 args->plot_path);
    if (!drawn) return fail(2, drawn.error().message);
  }
  if (args->json) {
    std::printf("%s\n", tools::planSummaryJson(plan.value()).c_str());
  } else {
    const auto& p = plan.value();
    std::printf("planned %s -> %s: %.3f s, min clearance %.4f m, plan %.2f ms (search %.2f, smooth %.2f, topp %.2f)\n",
                poseText(robot, args->from, from.value()).c_str(), poseText(robot, args->to, to.value()).c_str(),
                p.trajectory->duration_s(), p.min_clearance_m, p.times_ms.total, p.times_ms.search, p.times_ms.smooth,
                p.times_ms.topp);
  }
  return 0;
}

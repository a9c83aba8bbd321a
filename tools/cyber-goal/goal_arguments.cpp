#include "goal_arguments.hpp"

#include "cyber/cli/argument_parser.hpp"
#include "cyber/cli/number_text.hpp"
#include "pose_argument.hpp"

#include <algorithm>

namespace cyber::tools {

namespace {
// arm_goal_t counts pieces and joints in an int8_t; the daemon judges the counts itself.
constexpr size_t kMaxSentPieces = 127;
constexpr size_t kMaxSentJoints = 127;
}  // namespace

std::string goalUsage() {
  return "usage: cyber-goal --to J0,J1,...|NAME [--config FILE] [--pieces NAME[,NAME...]] [--scene NAME]\n"
         "                  [--scene-offset METRES] [--id N] [--lcm-url URL] [--timeout SECONDS] [--no-wait-daemon]\n"
         "Publishes one ARM_GOAL and prints each ARM_PLAN_STATUS of its request id until the final one.\n"
         "--to: targets of the joints in the config's [[joints]] order, metres (prismatic) or radians\n"
         "(revolute), or the name of a pose the daemon's configuration gives the held pieces ([poses.SET]\n"
         "tables), sent as the name; --config FILE (the robot description, read for no other purpose)\n"
         "checks the name before sending it.\n"
         "--pieces: held game pieces by the config's names (\"none\": none).\n"
         "First waits for cyber-plannerd's ARM_DAEMON_STATUS (unless --no-wait-daemon).\n"
         "--lcm-url defaults to " +
         std::string(config::kDefaultLcmUrl) +
         ", the daemon's default.\n"
         "Exit: 0 done, 3 rejected, 4 failed, 5 cancelled, 6 timed out, 2 bad arguments, 1 LCM error.\n";
}

Result<GoalArguments, cli::ArgumentStatus> parseGoalArguments(const std::vector<std::string>& args) {
  GoalArguments out;
  bool have_target = false;
  cli::ArgumentParser parser;
  parser.option("--pieces", [&](const std::string& value) -> std::string {
    out.pieces.clear();
    if (value == "none") return "";
    size_t from = 0;
    while (true) {
      const size_t end = value.find(',', from);
      std::string name = value.substr(from, end == std::string::npos ? std::string::npos : end - from);
      if (name.empty()) return "expects NAME[,NAME...], got '" + value + "'";
      out.pieces.push_back(std::move(name));
      if (end == std::string::npos) break;
      from = end + 1;
    }
    // arm_goal_t counts them in an int8_t; the daemon refuses more than MAX_PIECES itself.
    if (out.pieces.size() > kMaxSentPieces) return "expects at most 127 names, got '" + value + "'";
    return "";
  });
  parser.option("--scene-offset", [&](const std::string& value) -> std::string {
    const auto offset = cli::parseNumber(value, cli::NonFinite::kAccept);
    if (!offset) return "expects metres, got '" + value + "'";
    out.scene_offset_m = *offset;
    return "";
  });
  parser.flag("--no-wait-daemon", [&] { out.wait_for_daemon = false; });
  parser.option("--to", [&](const std::string& value) -> std::string {
    const auto target = parsePoseArgument(value, cli::NonFinite::kAccept);
    if (!target || target->values.size() > kMaxSentJoints)
      return "expects J0,J1,... or a pose NAME, got '" + value + "'";
    out.pose_name = target->name;
    out.position = target->values;
    have_target = true;
    return "";
  });
  parser.option("--config", cli::store(out.config_path));
  parser.option("--scene", cli::store(out.scene));
  parser.option("--id", [&](const std::string& value) -> std::string {
    const auto id = cli::parseInteger(value);
    if (!id) return "expects an integer, got '" + value + "'";
    out.request_id = *id;
    return "";
  });
  parser.option("--lcm-url", cli::store(out.lcm_url));
  parser.option("--timeout", [&](const std::string& value) -> std::string {
    const auto seconds = cli::parseNumber(value);
    if (!seconds || !(*seconds > 0.0)) return "expects seconds > 0, got '" + value + "'";
    out.timeout_s = *seconds;
    return "";
  });
  if (auto decided = parser.parseInto(args, out)) return *decided;
  if (!have_target) return cli::badUsage("--to J0,J1,... or --to NAME is required");
  return out;
}

Result<std::vector<double>, cli::ArgumentStatus> goalPosition(const GoalArguments& args, const config::Config& config) {
  if (args.pose_name.empty()) return args.position;
  std::string names;
  for (const std::string& piece : args.pieces) names.append(names.empty() ? "" : ",").append(piece);
  const auto held = config.robot.piecesNamed(names);
  if (!held) return cli::badUsage("--pieces: " + held.error().message);
  const auto q = resolvePose(PoseArgument{args.pose_name, {}}, config, held.value());
  if (!q) return cli::badUsage("--to: " + q.error().message);
  const planner::JointVector& pose = q.value();
  return std::vector<double>(pose.data(), pose.data() + pose.size());
}

}  // namespace cyber::tools

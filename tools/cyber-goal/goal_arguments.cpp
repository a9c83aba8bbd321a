#include "goal_arguments.hpp"

#include "cyber/cli/argument_parser.hpp"
#include "cyber/cli/number_text.hpp"

namespace cyber::tools {

std::string goalUsage() {
  return "usage: cyber-goal --to ELEVATOR_M,ARM_RAD [--coral] [--algae] [--scene NAME] [--id N]\n"
         "                  [--lcm-url URL] [--timeout SECONDS] [--no-wait-daemon]\n"
         "Publishes one ARM_GOAL and prints each ARM_PLAN_STATUS of its request id until the final one.\n"
         "First waits for cyber-plannerd's ARM_DAEMON_STATUS (unless --no-wait-daemon).\n"
         "--lcm-url defaults to " +
         std::string(config::kDefaultLcmUrl) +
         ", the daemon's default.\n"
         "Exit: 0 done, 3 rejected, 4 failed, 5 cancelled, 6 timed out, 2 bad arguments, 1 LCM error.\n";
}

cli::Parsed<GoalArguments> parseGoalArguments(const std::vector<std::string>& args) {
  GoalArguments out;
  bool have_target = false;
  cli::ArgumentParser parser;
  parser.flag("--coral", [&] { out.coral = true; });
  parser.flag("--algae", [&] { out.algae = true; });
  parser.flag("--no-wait-daemon", [&] { out.wait_for_daemon = false; });
  parser.option("--to", [&](const std::string& value) -> std::string {
    const auto target = cli::parseNumberPair(value, cli::NonFinite::kAccept);
    if (!target) return "expects ELEVATOR_M,ARM_RAD, got '" + value + "'";
    out.elevator_m = (*target)[0];
    out.arm_rad = (*target)[1];
    have_target = true;
    return "";
  });
  parser.option("--scene", cli::store(&out.scene));
  parser.option("--id", [&](const std::string& value) -> std::string {
    const auto id = cli::parseInteger(value);
    if (!id) return "expects an integer, got '" + value + "'";
    out.request_id = *id;
    return "";
  });
  parser.option("--lcm-url", cli::store(&out.lcm_url));
  parser.option("--timeout", [&](const std::string& value) -> std::string {
    const auto seconds = cli::parseNumber(value);
    if (!seconds || !(*seconds > 0.0)) return "expects seconds > 0, got '" + value + "'";
    out.timeout_s = *seconds;
    return "";
  });
  if (auto decided = parser.parseInto(args, out)) return *decided;
  if (!have_target) return cli::ArgumentError{"--to ELEVATOR_M,ARM_RAD is required"};
  return out;
}

}  // namespace cyber::tools

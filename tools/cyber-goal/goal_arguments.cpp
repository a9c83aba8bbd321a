#include "goal_arguments.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace cyber::tools {

namespace {

bool parseDouble(const std::string& text, double& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno == 0;
}

}  // namespace

std::string goalUsage() {
  return "usage: cyber-goal --to ELEVATOR_M,ARM_RAD [--coral] [--algae] [--scene NAME] [--id N]\n"
         "                  [--lcm-url URL] [--timeout SECONDS] [--no-wait-daemon]\n"
         "Publishes one ARM_GOAL and prints each ARM_PLAN_STATUS of its request id until the final one.\n"
         "First waits for cyber-plannerd's ARM_DAEMON_STATUS (unless --no-wait-daemon).\n"
         "Exit: 0 done, 3 rejected, 4 failed, 5 cancelled, 6 timed out, 2 bad arguments, 1 LCM error.\n";
}

std::variant<GoalArguments, GoalArgumentError> parseGoalArguments(const std::vector<std::string>& args) {
  GoalArguments out;
  bool have_target = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      out.help = true;
      return out;
    }
    if (arg == "--coral") {
      out.coral = true;
      continue;
    }
    if (arg == "--algae") {
      out.algae = true;
      continue;
    }
    if (arg == "--no-wait-daemon") {
      out.wait_for_daemon = false;
      continue;
    }
    const bool takes_value = arg == "--to" || arg == "--scene" || arg == "--id" || arg == "--lcm-url" || arg == "--timeout";
    if (!takes_value) return GoalArgumentError{"unknown argument '" + arg + "'"};
    if (i + 1 >= args.size()) return GoalArgumentError{arg + " needs a value"};
    const std::string& value = args[++i];
    if (arg == "--to") {
      const auto comma = value.find(',');
      if (comma == std::string::npos || !parseDouble(value.substr(0, comma), out.elevator_m) ||
          !parseDouble(value.substr(comma + 1), out.arm_rad)) {
        return GoalArgumentError{"--to expects ELEVATOR_M,ARM_RAD, got '" + value + "'"};
      }
      have_target = true;
    } else if (arg == "--scene") {
      out.scene = value;
    } else if (arg == "--id") {
      char* end = nullptr;
      errno = 0;
      const long long id = std::strtoll(value.c_str(), &end, 10);
      if (value.empty() || end != value.c_str() + value.size() || errno != 0) {
        return GoalArgumentError{"--id expects an integer, got '" + value + "'"};
      }
      out.request_id = id;
    } else if (arg == "--lcm-url") {
      out.lcm_url = value;
    } else {
      if (!parseDouble(value, out.timeout_s) || !(out.timeout_s > 0.0) || !std::isfinite(out.timeout_s)) {
        return GoalArgumentError{"--timeout expects seconds > 0, got '" + value + "'"};
      }
    }
  }
  if (!have_target) return GoalArgumentError{"--to ELEVATOR_M,ARM_RAD is required"};
  return out;
}

}  // namespace cyber::tools

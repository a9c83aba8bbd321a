#include "robot_arguments.hpp"

#include "cyber/cli/argument_parser.hpp"

namespace cyber::tools {

const char* robotUsage() {
  return "usage: cyber-robot check ROBOT.toml [--png FILE.png]\n"
         "Checks a robot description before its first plan: each named pose's clearance in each scene,\n"
         "which poses the planner joins (every ordered pair of each [poses.SET] in the default scene),\n"
         "whether each drive holds and moves its load with the heaviest held set, and the planner\n"
         "settings in use. Exit 0: no error (warnings allowed); 1: an error, or a description that does\n"
         "not load; 2: bad usage.\n"
         "  --png FILE.png  also draw the robot at its named poses over the default scene\n";
}

Result<RobotArguments, cli::ArgumentStatus> parseRobotArguments(const std::vector<std::string>& args) {
  RobotArguments out;
  std::vector<std::string> words;
  cli::ArgumentParser parser;
  parser.option("--png", cli::store(out.png_path));
  parser.positional([&](const std::string& value) -> std::string {
    words.push_back(value);
    return "";
  });
  if (auto decided = parser.parseInto(args, out)) return *decided;
  if (words.empty()) return cli::badUsage("missing the command (check)");
  if (words[0] != "check") return cli::badUsage("unknown command '" + words[0] + "' (the command is check)");
  if (words.size() != 2) return cli::badUsage("check takes one robot description: cyber-robot check ROBOT.toml");
  out.command = words[0];
  out.config_path = words[1];
  return out;
}

}  // namespace cyber::tools

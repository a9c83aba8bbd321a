#pragma once
// The command line of cyber-robot (usage in robotUsage()).

#include <string>
#include <vector>

#include "cyber/cli/argument_status.hpp"

namespace cyber::tools {

struct RobotArguments {
  std::string command;      // "check"
  std::string config_path;  // the robot description
  std::string png_path;     // empty: no picture
  bool help = false;
};

Result<RobotArguments, cli::ArgumentStatus> parseRobotArguments(const std::vector<std::string>& args);

const char* robotUsage();

}  // namespace cyber::tools

#pragma once
// The command line of cyber-wpilog (usage in wpilogUsage()).

#include <string>
#include <vector>

#include "cyber/cli/argument_status.hpp"

namespace cyber::tools {

struct WpilogArguments {
  std::string config_path;  // empty: the embedded reference robot
  std::string list_path;    // --list FILE: list it instead of converting
  std::string lcm_log_path;
  std::string wpilog_path;
  bool help = false;
};

// Either --list FILE alone, or IN.lcmlog OUT.wpilog.
Result<WpilogArguments, cli::ArgumentStatus> parseWpilogArguments(const std::vector<std::string>& args);

const char* wpilogUsage();

}  // namespace cyber::tools

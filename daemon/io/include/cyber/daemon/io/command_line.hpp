#pragma once
// cyber-plannerd [--config FILE] [--can IFACE|none] [--lcm-url URL] [--help]

#include <optional>
#include <string>
#include <vector>

#include "cyber/cli/argument_status.hpp"

namespace cyber::daemon::io {

struct CommandLine {
  std::string config_path;                   // empty: the embedded default configuration
  std::optional<std::string> can_interface;  // "none" = simulation
  std::optional<std::string> lcm_url;
  bool help = false;
};

// Parses argv[1..]; an error message names the offending argument.
Result<CommandLine, cli::ArgumentStatus> parseCommandLine(const std::vector<std::string>& args);

std::string usage();

}  // namespace cyber::daemon::io

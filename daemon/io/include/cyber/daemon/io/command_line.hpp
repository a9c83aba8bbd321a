#pragma once
// cyber-plannerd [--config FILE] [--can IFACE|none] [--lcm-url URL] [--help]

#include <optional>
#include <variant>
#include <string>
#include <vector>

namespace cyber::daemon::io {

struct CommandLine {
  std::string config_path;  // empty: the embedded default configuration
  std::optional<std::string> can_interface;  // "none" = simulation
  std::optional<std::string> lcm_url;
  bool help = false;
};

struct CommandLineError {
  std::string message;
};

// Parses argv[1..]; an error message names the offending argument.
std::variant<CommandLine, CommandLineError> parseCommandLine(const std::vector<std::string>& args);

std::string usage();

}  // namespace cyber::daemon::io

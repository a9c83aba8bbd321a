#include "cyber/daemon/io/command_line.hpp"

#include "cyber/cli/argument_parser.hpp"

namespace cyber::daemon::io {

std::string usage() {
  return "usage: cyber-plannerd [--config FILE] [--can IFACE|none] [--lcm-url URL]\n"
         "  --config FILE    robot and daemon configuration (TOML, see docs/configuration.md);\n"
         "                   default: the embedded reference robot (config/reefscape-2025.toml)\n"
         "  --can IFACE      SocketCAN interface for setpoints (default: [daemon] can_interface);\n"
         "                   'none' = simulation: no CAN writes, robot-enabled gate open\n"
         "  --lcm-url URL    LCM URL (default: [daemon] lcm_url)\n"
         "  --help           this text\n";
}

Result<CommandLine, cli::ArgumentStatus> parseCommandLine(const std::vector<std::string>& args) {
  CommandLine out;
  cli::ArgumentParser parser;
  parser.option("--config", cli::store(out.config_path));
  parser.option("--can", cli::store(out.can_interface));
  parser.option("--lcm-url", cli::store(out.lcm_url));
  if (auto decided = parser.parseInto(args, out)) return *decided;
  return out;
}

}  // namespace cyber::daemon::io

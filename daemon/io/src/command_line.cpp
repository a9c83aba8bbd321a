#include "cyber/daemon/io/command_line.hpp"

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

std::variant<CommandLine, CommandLineError> parseCommandLine(const std::vector<std::string>& args) {
  CommandLine out;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      out.help = true;
      return out;
    }
    if (arg == "--config" || arg == "--can" || arg == "--lcm-url") {
      if (i + 1 >= args.size() || args[i + 1].empty()) return CommandLineError{arg + " needs a value"};
      const std::string& value = args[++i];
      if (arg == "--config") {
        out.config_path = value;
      } else if (arg == "--can") {
        out.can_interface = value;
      } else {
        out.lcm_url = value;
      }
      continue;
    }
    return CommandLineError{"unknown argument '" + arg + "'"};
  }
  return out;
}

}  // namespace cyber::daemon::io

#include "wpilog_arguments.hpp"

#include "cyber/cli/argument_parser.hpp"

namespace cyber::tools {

const char* wpilogUsage() {
  return "usage: cyber-wpilog [--config FILE] IN.lcmlog OUT.wpilog\n"
         "       cyber-wpilog --list FILE.wpilog\n"
         "Converts a session recorded by lcm-logger into a WPILOG that AdvantageScope opens: entries\n"
         "under /CyberPlanner/ for setpoints, measured state, goals, plan status, trajectories, the\n"
         "daemon's mode and counters, and the mechanism as a Mechanism2d (a ligament per joint) and\n"
         "as 3-D component poses (one per link).\n"
         "  --config FILE  robot description for the mechanism (default: the embedded\n"
         "                 config/reefscape-2025.toml); its [daemon.channels] name the channels\n"
         "  --list FILE    print every entry of a .wpilog: name, type, records, last value\n";
}

Result<WpilogArguments, cli::ArgumentStatus> parseWpilogArguments(const std::vector<std::string>& args) {
  WpilogArguments out;
  std::vector<std::string> files;
  cli::ArgumentParser parser;
  parser.option("--config", cli::store(out.config_path));
  parser.option("--list", cli::store(out.list_path));
  parser.positional([&](const std::string& file) {
    files.push_back(file);
    return std::string();
  });
  if (auto decided = parser.parseInto(args, out)) return *decided;
  if (!out.list_path.empty()) {
    if (!files.empty()) return cli::badUsage("--list takes no other files");
    return out;
  }
  if (files.size() != 2) return cli::badUsage("expected IN.lcmlog OUT.wpilog (see --help)");
  out.lcm_log_path = files[0];
  out.wpilog_path = files[1];
  return out;
}

}  // namespace cyber::tools

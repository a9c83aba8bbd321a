#pragma once
// The command line of cyber-plot (usage in plotUsage()).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cyber/cli/argument_status.hpp"
#include "cyber/planner.hpp"

namespace cyber::tools {

struct PlotArguments {
  std::string config_path;  // empty: the embedded reference robot
  std::string csv_path;
  std::string log_path;
  std::string channel;  // empty: the config's trajectory channel
  std::optional<std::int64_t> request_id;
  std::string scene;
  std::string out_path;
  std::string animation_path;
  std::optional<planner::JointVector> at;  // --at: 1 to kMaxJoints finite values (main checks the count)
  std::string at_text;                     // --at as given, for messages
  bool world = false;
  int frames = 6;
  std::string pieces;  // --pieces as given; resolved against the robot
  bool help = false;

  // Only --config (no --world, --csv or --lcm-log): a preview of the description.
  [[nodiscard]] bool preview() const { return !world && csv_path.empty() && log_path.empty() && !config_path.empty(); }
};

// Also checks the combinations (exactly one source, --animation only with --world, ...).
Result<PlotArguments, cli::ArgumentStatus> parsePlotArguments(const std::vector<std::string>& args);

const char* plotUsage();

}  // namespace cyber::tools

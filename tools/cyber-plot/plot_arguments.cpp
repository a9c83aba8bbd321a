#include "plot_arguments.hpp"

#include <optional>
#include <string_view>

#include "cyber/cli/argument_parser.hpp"
#include "cyber/cli/number_text.hpp"

namespace cyber::tools {
namespace {

// "Q0,Q1,...": 1 to kMaxJoints finite numbers, one comma between each two (main checks the count
// against the robot).
std::optional<planner::JointVector> jointPositions(const std::string& text) {
  std::vector<double> values;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const auto value = cli::parseNumber(std::string_view(text).substr(start, comma - start));
    if (!value || values.size() == static_cast<size_t>(planner::kMaxJoints)) return std::nullopt;
    values.push_back(*value);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  planner::JointVector q(static_cast<Eigen::Index>(values.size()));
  for (size_t j = 0; j < values.size(); ++j) q[static_cast<Eigen::Index>(j)] = values[j];
  return q;
}

}  // namespace

const char* plotUsage() {
  return "usage: cyber-plot [--config FILE] (--csv FILE | --lcm-log FILE [--channel NAME] [--request-id N])\n"
         "                  [--pieces NAME,...] [--scene NAME] --out FILE.png\n"
         "       cyber-plot --world [--config FILE] (--at Q0,... | --csv FILE | --lcm-log FILE ...)\n"
         "                  [--frames N] [--animation FILE.png] [--pieces NAME,...] [--scene NAME] --out FILE.png\n"
         "       cyber-plot --config FILE [--pieces NAME,...] [--scene NAME] --out FILE.png\n"
         "Draws the C-space (obstacle region of the held pieces) with the path, and position, velocity,\n"
         "voltage and current against time with the limits, like cyber-plan --plot.\n"
         "  --csv FILE        a trajectory written by cyber-plan --csv\n"
         "  --lcm-log FILE    an lcm-logger log; plots its last ARM_TRAJECTORY (or the one of --request-id)\n"
         "  --config FILE     robot description (default: the embedded config/reefscape-2025.toml); alone,\n"
         "                    previews it: the robot at its named poses ([poses.*] of the held pieces) over\n"
         "                    the obstacles, and the C-space map with those poses\n"
         "  --world           the side view of the scene with the robot: at --at (one position per joint,\n"
         "                    chain order), or for a trajectory a filmstrip of --frames poses (default 6)\n"
         "                    plus the pose of smallest clearance\n"
         "  --animation FILE  with --world and a trajectory: also an animated PNG (APNG, 25 frames/s)\n";
}

Result<PlotArguments, cli::ArgumentStatus> parsePlotArguments(const std::vector<std::string>& args) {
  PlotArguments out;
  cli::ArgumentParser parser;
  parser.flag("--world", [&] { out.world = true; });
  parser.option("--pieces", cli::store(out.pieces));
  parser.option("--config", cli::store(out.config_path));
  parser.option("--csv", cli::store(out.csv_path));
  parser.option("--lcm-log", cli::store(out.log_path));
  parser.option("--channel", cli::store(out.channel));
  parser.option("--scene", cli::store(out.scene));
  parser.option("--out", cli::store(out.out_path));
  parser.option("--animation", cli::store(out.animation_path));
  parser.option("--frames", [&](const std::string& value) -> std::string {
    const auto frames = cli::parseInteger(value);
    if (!frames || *frames < 2 || *frames > 20) return "expects 2 to 20, got '" + value + "'";
    out.frames = static_cast<int>(*frames);
    return "";
  });
  parser.option("--request-id", [&](const std::string& value) -> std::string {
    out.request_id = cli::parseInteger(value);
    return out.request_id ? "" : "expects an integer, got '" + value + "'";
  });
  parser.option("--at", [&](const std::string& value) -> std::string {
    const auto q = jointPositions(value);
    if (!q)
      return "expects Q0,... (one position per joint, at most " + std::to_string(planner::kMaxJoints) + "), got '" +
             value + "'";
    out.at = *q;
    out.at_text = value;
    return "";
  });
  if (auto decided = parser.parseInto(args, out)) return *decided;
  if (out.out_path.empty()) return cli::badUsage("missing --out FILE.png");
  if (!out.world && (!out.animation_path.empty() || out.at)) return cli::badUsage("--animation and --at need --world");
  const int sources = (out.csv_path.empty() ? 0 : 1) + (out.log_path.empty() ? 0 : 1) + (out.at ? 1 : 0);
  if (!out.preview() && sources != 1) {
    return cli::badUsage(out.world ? "give exactly one of --at, --csv and --lcm-log"
                                   : "give exactly one of --csv and --lcm-log");
  }
  if (out.at && !out.animation_path.empty()) {
    return cli::badUsage("--animation needs a trajectory (--csv or --lcm-log), not --at");
  }
  return out;
}

}  // namespace cyber::tools

#include "plan_arguments.hpp"

#include "cyber/cli/argument_parser.hpp"
#include "cyber/cli/number_text.hpp"

#include <utility>

namespace cyber::tools {

const char* planUsage() {
  return "usage: cyber-plan [--config FILE] --from POSE --to POSE [--pieces NAME,...]\n"
         "                  [--from-velocity V0,V1] [--scene NAME] [--scene-offset METRES] [--csv FILE] [--json]\n"
         "                  [--csv-step SECONDS] [--plot FILE.png]\n"
         "Plans one move of the robot's joints and prints a summary. A POSE is the joints' values in chain\n"
         "order (Q0,Q1: m or rad) or the name of a pose the configuration gives the held pieces\n"
         "([poses.SET] tables: STOW, L3, ...).\n"
         "  --config FILE       robot description (default: the embedded config/reefscape-2025.toml)\n"
         "  --pieces NAME,...   game pieces held during the move, as the configuration names them\n"
         "  --from-velocity     start velocity (joint units per second); default at rest\n"
         "  --scene NAME        obstacle scene of the configuration (default: its first scene)\n"
         "  --scene-offset M    shift of the scene's field elements in x (> 0: the robot further away)\n"
         "  --csv FILE          the trajectory at 1 ms: t, then per joint NAME_pos,NAME_vel,NAME_acc,\n"
         "                      NAME_volts,NAME_amps\n"
         "  --csv-step SECONDS  the CSV's sample spacing, 0.00001 to 0.001 (default: 1 ms, or the widest\n"
         "                      spacing whose samples describe the motion: columns that integrate to\n"
         "                      each other, a path whose turns they resolve; stderr then says so)\n"
         "  --json              print one JSON object: duration, stage times, solver residuals, clearance\n"
         "  --plot FILE.png     draw the C-space with the path and the joint signals with their limits\n"
         "Exit status: 0 planned, 2 bad input, 3 no feasible motion.\n";
}

namespace {

// Stores a pose argument into `into`, or says what was expected.
cli::ValueHandler pose(PoseArgument* into, bool* given) {
  return [into, given](const std::string& text) -> std::string {
    auto parsed = parsePoseArgument(text);
    if (!parsed) return parsed.error().message;
    *into = std::move(parsed).value();
    *given = true;
    return "";
  };
}

// Stores "A,B,..." (one finite number per joint; main checks the count against the robot) into
// `into`, or says what was expected.
cli::ValueHandler jointValues(planner::JointVector* into, const char* what) {
  return [into, what](const std::string& text) -> std::string {
    const auto parsed = parsePoseArgument(text, cli::NonFinite::kReject);
    if (!parsed || !parsed.value().name.empty() || parsed.value().values.size() > planner::kMaxJoints) {
      return std::string("expects ") + what + " as one finite number per joint separated by ',', got '" + text + "'";
    }
    const std::vector<double>& values = parsed.value().values;
    *into = planner::JointVector(static_cast<Eigen::Index>(values.size()));
    for (size_t j = 0; j < values.size(); ++j) (*into)[static_cast<Eigen::Index>(j)] = values[j];
    return "";
  };
}

}  // namespace

Result<PlanArguments, cli::ArgumentStatus> parsePlanArguments(const std::vector<std::string>& args) {
  PlanArguments out;
  bool have_from = false;
  bool have_to = false;
  cli::ArgumentParser parser;
  parser.option("--config", cli::store(out.config_path));
  parser.option("--from", pose(&out.from, &have_from));
  parser.option("--to", pose(&out.to, &have_to));
  parser.option("--from-velocity", jointValues(&out.from_velocity, "V0,V1,..."));
  parser.option("--pieces", cli::store(out.pieces));
  parser.option("--scene", cli::store(out.scene));
  parser.option("--scene-offset", [&](const std::string& value) -> std::string {
    const auto offset = cli::parseNumber(value);
    if (!offset) return "expects a finite number of metres, got '" + value + "'";
    out.scene_offset_m = *offset;
    return "";
  });
  parser.option("--csv", cli::store(out.csv_path));
  parser.option("--csv-step", [&](const std::string& value) -> std::string {
    const auto step = cli::parseNumber(value);
    if (!step || *step < kMinCsvStepS || *step > kMaxCsvStepS)
      return "expects seconds from 0.00001 to 0.001, got '" + value + "'";
    out.csv_step_s = *step;
    return "";
  });
  parser.option("--plot", cli::store(out.plot_path));
  parser.flag("--json", [&] { out.json = true; });
  if (auto decided = parser.parseInto(args, out)) return *decided;
  if (!have_from || !have_to)
    return cli::badUsage(std::string("missing ") + (have_from ? "--to" : "--from") + " (see --help)");
  return out;
}

}  // namespace cyber::tools

#include "plan_arguments.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace cyber::tools {

const char* planUsage() {
  return "usage: cyber-plan [--config FILE] --from T,THETA --to T,THETA [--coral] [--algae]\n"
         "                  [--from-velocity VT,VTHETA] [--scene NAME] [--csv FILE] [--json] [--plot FILE.png]\n"
         "Plans one move of the elevator (T, m) and arm (THETA, rad) and prints a summary.\n"
         "  --config FILE       robot description (default: the embedded config/reefscape-2025.toml)\n"
         "  --coral, --algae    game pieces held during the move\n"
         "  --from-velocity     start velocity (m/s, rad/s); default at rest\n"
         "  --scene NAME        obstacle scene of the configuration (default: its first scene)\n"
         "  --csv FILE          the trajectory at 1 ms: t,elevator_m,elevator_mps,elevator_mps2,arm_rad,arm_radps,\n"
         "                      arm_radps2,elevator_volts,arm_volts,elevator_amps,arm_amps\n"
         "  --json              print one JSON object: duration, stage times, solver residuals, clearance\n"
         "  --plot FILE.png     draw the C-space with the path and the joint signals with their limits\n"
         "Exit status: 0 planned, 2 bad input, 3 no feasible motion.\n";
}

std::optional<planner::JointVector> parsePair(const std::string& text) {
  const size_t comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) return std::nullopt;
  planner::JointVector out;
  const std::string parts[2] = {text.substr(0, comma), text.substr(comma + 1)};
  for (int i = 0; i < 2; ++i) {
    if (parts[i].empty()) return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(parts[i].c_str(), &end);
    if (end != parts[i].c_str() + parts[i].size() || errno == ERANGE || !std::isfinite(x)) return std::nullopt;
    out[i] = x;
  }
  return out;
}

std::optional<PlanArguments> parsePlanArguments(const std::vector<std::string>& args, std::string* error) {
  PlanArguments out;
  bool have_from = false;
  bool have_to = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string* into) {
      if (i + 1 >= args.size()) {
        *error = a + " needs a value";
        return false;
      }
      *into = args[++i];
      return true;
    };
    auto pair = [&](planner::JointVector* into, const char* what) {
      std::string text;
      if (!value(&text)) return false;
      const auto p = parsePair(text);
      if (!p) {
        *error = a + " expects " + what + " as two finite numbers separated by a comma, got \"" + text + "\"";
        return false;
      }
      *into = *p;
      return true;
    };
    if (a == "--help" || a == "-h") {
      out.help = true;
    } else if (a == "--config") {
      if (!value(&out.config_path)) return std::nullopt;
    } else if (a == "--from") {
      if (!pair(&out.from, "T,THETA")) return std::nullopt;
      have_from = true;
    } else if (a == "--to") {
      if (!pair(&out.to, "T,THETA")) return std::nullopt;
      have_to = true;
    } else if (a == "--from-velocity") {
      if (!pair(&out.from_velocity, "VT,VTHETA")) return std::nullopt;
    } else if (a == "--coral") {
      out.pieces.coral = true;
    } else if (a == "--algae") {
      out.pieces.algae = true;
    } else if (a == "--scene") {
      if (!value(&out.scene)) return std::nullopt;
    } else if (a == "--csv") {
      if (!value(&out.csv_path)) return std::nullopt;
    } else if (a == "--plot") {
      if (!value(&out.plot_path)) return std::nullopt;
    } else if (a == "--json") {
      out.json = true;
    } else {
      *error = "unknown argument \"" + a + "\" (see --help)";
      return std::nullopt;
    }
  }
  if (out.help) return out;
  if (!have_from || !have_to) {
    *error = std::string("missing ") + (have_from ? "--to" : "--from") + " (see --help)";
    return std::nullopt;
  }
  return out;
}

}  // namespace cyber::tools

#pragma once
// The command line of cyber-plan, parsed strictly: anything malformed is an error message.

#include <optional>
#include <string>
#include <vector>

#include "cyber/cli/parsed.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::tools {

// The CSV's sample spacing: 1 ms by default, the widest an external referee takes; --csv-step
// chooses from 10 us (t is printed to the microsecond) up to that. Without it, a trajectory whose
// columns disagree at 1 ms is written at the widest of kCsvSteps at which they agree
// (csvStepFor, plan_output.hpp).
inline constexpr double kCsvStepS = 1e-3;
inline constexpr double kMinCsvStepS = 1e-5;
inline constexpr double kMaxCsvStepS = kCsvStepS;
inline constexpr double kCsvSteps[] = {kCsvStepS, 5e-4, 2.5e-4, 1e-4, 5e-5, 2.5e-5, kMinCsvStepS};

struct PlanArguments {
  std::string config_path;  // empty: the embedded reference robot
  planner::JointVector from = planner::JointVector::Zero();
  planner::JointVector to = planner::JointVector::Zero();
  planner::JointVector from_velocity = planner::JointVector::Zero();
  std::string pieces;  // names as --pieces gives them; resolved against the robot
  std::string scene;   // empty: the default scene
  double scene_offset_m = 0.0;
  std::string csv_path;
  std::optional<double> csv_step_s;  // spacing of the CSV's samples (--csv-step); none: csvStepFor
  std::string plot_path;
  bool json = false;
  bool help = false;
};

cli::Parsed<PlanArguments> parsePlanArguments(const std::vector<std::string>& args);

const char* planUsage();

}  // namespace cyber::tools

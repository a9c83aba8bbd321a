#pragma once
// The command line of cyber-plan, parsed strictly: anything malformed is an error message.

#include <string>
#include <vector>

#include "cyber/cli/parsed.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::tools {

// --csv-step: 10 us to 1 ms (an external referee takes samples at most 1 ms apart; t is printed to
// the microsecond).
inline constexpr double kMinCsvStepS = 1e-5;
inline constexpr double kMaxCsvStepS = 1e-3;

struct PlanArguments {
  std::string config_path;  // empty: the embedded reference robot
  planner::JointVector from = planner::JointVector::Zero();
  planner::JointVector to = planner::JointVector::Zero();
  planner::JointVector from_velocity = planner::JointVector::Zero();
  std::string pieces;  // names as --pieces gives them; resolved against the robot
  std::string scene;   // empty: the default scene
  double scene_offset_m = 0.0;
  std::string csv_path;
  double csv_step_s = 0.001;  // spacing of the CSV's samples (--csv-step), within kCsvStepRangeS
  std::string plot_path;
  bool json = false;
  bool help = false;
};

cli::Parsed<PlanArguments> parsePlanArguments(const std::vector<std::string>& args);

const char* planUsage();

}  // namespace cyber::tools

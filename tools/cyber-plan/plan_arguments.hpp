#pragma once
// The command line of cyber-plan, parsed strictly: anything malformed is an error message.

#include <string>
#include <vector>

#include "cyber/cli/parsed.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::tools {

struct PlanArguments {
  std::string config_path;  // empty: the embedded reference robot
  planner::JointVector from = planner::JointVector::Zero();
  planner::JointVector to = planner::JointVector::Zero();
  planner::JointVector from_velocity = planner::JointVector::Zero();
  std::string pieces;  // names as --pieces gives them; resolved against the robot
  std::string scene;   // empty: the default scene
  double scene_offset_m = 0.0;
  std::string csv_path;
  std::string plot_path;
  bool json = false;
  bool help = false;
};

cli::Parsed<PlanArguments> parsePlanArguments(const std::vector<std::string>& args);

const char* planUsage();

}  // namespace cyber::tools

#pragma once
// The command line of cyber-plan, parsed strictly: anything malformed is an error message.

#include <optional>
#include <string>
#include <vector>

#include "cyber/planner/types.hpp"

namespace cyber::tools {

struct PlanArguments {
  std::string config_path;  // empty: the embedded reference robot
  planner::JointVector from = planner::JointVector::Zero();
  planner::JointVector to = planner::JointVector::Zero();
  planner::JointVector from_velocity = planner::JointVector::Zero();
  planner::HeldPieces pieces;
  std::string scene;  // empty: the default scene
  std::string csv_path;
  std::string plot_path;
  bool json = false;
  bool help = false;
};

// Returns the arguments, or sets `error` to a one-line reason.
std::optional<PlanArguments> parsePlanArguments(const std::vector<std::string>& args, std::string* error);

// Parses "A,B" into two finite numbers.
std::optional<planner::JointVector> parsePair(const std::string& text);

const char* planUsage();

}  // namespace cyber::tools

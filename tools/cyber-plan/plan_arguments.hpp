#pragma once
// The command line of cyber-plan, parsed strictly: anything malformed is an error message.

#include <optional>
#include <string>
#include <vector>

#include "cyber/cli/argument_status.hpp"
#include "cyber/planner.hpp"
#include "pose_argument.hpp"

namespace cyber::tools {

// The CSV's sample spacing: 1 ms by default, the widest an external referee takes; --csv-step
// chooses from 10 us (t is printed to the microsecond) up to that. Without it, a trajectory that
// its 1 ms samples do not describe is written at the widest of kCsvSteps that does (csvSpacingFor,
// plan_output.hpp).
inline constexpr double kCsvStepS = 1e-3;
inline constexpr double kMinCsvStepS = 1e-5;
inline constexpr double kMaxCsvStepS = kCsvStepS;
inline constexpr double kCsvSteps[] = {kCsvStepS, 5e-4, 2.5e-4, 1e-4, 5e-5, 2.5e-5, kMinCsvStepS};
// Samples describe the path when the fastest ride along them (cyber/planner/trajectory.hpp) is
// at most this share faster than the plan. A plan from rest is within about 0.5 % of that ride on
// samples 10 us apart (its TOPP grid's share); samples that let it pass a turn or the end at rest faster,
// where the path's tangent goes to zero, would show a check a path faster than the motors can
// ride it (docs/moving-starts.md, "The CSV's spacing").
inline constexpr double kCsvRideShare = 0.01;

struct PlanArguments {
  std::string config_path;  // empty: the embedded reference robot
  PoseArgument from;        // numbers or a name of the held set's poses; resolvePose with the config
  PoseArgument to;
  planner::JointVector from_velocity;
  std::string pieces;  // names as --pieces gives them; resolved against the robot
  std::string scene;   // empty: the default scene
  double scene_offset_m = 0.0;
  std::string csv_path;
  std::optional<double> csv_step_s;  // spacing of the CSV's samples (--csv-step); none: csvSpacingFor
  std::string plot_path;
  bool json = false;
  bool help = false;
};

Result<PlanArguments, cli::ArgumentStatus> parsePlanArguments(const std::vector<std::string>& args);

const char* planUsage();

}  // namespace cyber::tools

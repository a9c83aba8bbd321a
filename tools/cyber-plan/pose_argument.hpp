#pragma once
// A pose on the command line (cyber-plan --from/--to, cyber-goal --to): the joints' values in
// chain order, or the name of one of the poses a configuration's [poses.SET] tables give the
// held set (docs/configuration.md, "Named poses"). Reading the text needs no robot; what the
// numbers or the name mean is decided against the configuration.

#include <string>
#include <string_view>
#include <vector>

#include "cyber/cli/argument_status.hpp"
#include "cyber/cli/number_text.hpp"
#include "cyber/config/load_config.hpp"

namespace cyber::tools {

struct PoseArgument {
  std::string name;            // a pose of the held set's table; empty: `values` are the pose
  std::vector<double> values;  // joint units (m or rad), chain order; as many as given
};

// Numbers separated by ',' (non-finite ones only with NonFinite::kAccept), or else a name: text
// without a comma that is not a number. The message (to follow the option's name) says which.
Result<PoseArgument, cli::ArgumentStatus> parsePoseArgument(std::string_view text,
                                                            cli::NonFinite non_finite = cli::NonFinite::kReject);

// The pose in joint units: the values when there are as many as the robot has joints, or the
// pose `name` of the set of `held` pieces. A name the set does not declare is an error that lists
// the names it does (and the sets that declare the name, if any).
// The pose `name` of the set of `held` pieces among `poses` (a configuration's [poses.SET] tables
// of `robot`), or an error that lists the names the set declares and the other sets that declare
// `name`. The one lookup of named poses: cyber-plan and cyber-goal (through resolvePose) and the
// daemon for ARM_GOAL's pose_name.
Result<planner::JointVector, cli::ArgumentStatus> namedPose(const std::vector<config::PoseSet>& poses,
                                                            const planner::RobotModel& robot, planner::HeldPieces held,
                                                            const std::string& name);

Result<planner::JointVector, cli::ArgumentStatus> resolvePose(const PoseArgument& pose, const config::Config& config,
                                                              planner::HeldPieces held);

}  // namespace cyber::tools

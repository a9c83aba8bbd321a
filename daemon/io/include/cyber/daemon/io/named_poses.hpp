#pragma once
// ARM_GOAL's pose_name resolved with the daemon's configuration: the [poses.SET] tables, by the
// same lookup as cyber-plan's and cyber-goal's --to NAME (tools/cyber-plan/pose_argument.hpp), so
// a name means one pose everywhere (docs/lcm.md, "Named goals").

#include <vector>

#include "cyber/config/load_config.hpp"
#include "cyber/daemon/goal_request.hpp"

namespace cyber::daemon::io {

// A name the held set does not declare is kInvalidInput, its message listing the set's poses.
PoseLookup namedPoseLookup(std::vector<config::PoseSet> poses, const planner::RobotModel& robot);

}  // namespace cyber::daemon::io

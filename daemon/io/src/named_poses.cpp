#include "cyber/daemon/io/named_poses.hpp"

#include <memory>
#include <utility>

#include "pose_argument.hpp"

namespace cyber::daemon::io {

PoseLookup namedPoseLookup(std::vector<config::PoseSet> poses, const planner::RobotModel& robot) {
  // Shared, so that copies of the settings that carry the lookup do not copy the tables.
  auto table = std::make_shared<const std::vector<config::PoseSet>>(std::move(poses));
  return [table, &robot](planner::HeldPieces held, const std::string& name) -> planner::Result<planner::JointVector> {
    auto pose = tools::namedPose(*table, robot, held, name);
    if (!pose)
      return planner::Result<planner::JointVector>::failure(planner::PlanStatus::kInvalidInput, pose.error().message);
    return pose.value();
  };
}

}  // namespace cyber::daemon::io

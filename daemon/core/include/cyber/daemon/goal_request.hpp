#pragma once
// A goal as it arrives (ARM_GOAL fields) and its validation against the robot model. Every
// problem is a PlanError whose reason names the field, and joints by the config's names.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "cyber/planner.hpp"

namespace cyber::daemon {

// The most pieces a goal may name (arm_goal_t::MAX_PIECES; the planner's own limit).
inline constexpr int kMaxGoalPieces = planner::HeldPieces::kMaxPieces;

struct GoalRequest {
  std::int64_t request_id = 0;
  // "" = `position` is the target; else a pose of the config's [poses.SET] for the held pieces,
  // and `position` is ignored (docs/lcm.md, "Named goals").
  std::string pose_name;
  // The target of each joint as sent (config [[joints]] order), each in its joint's unit (m or
  // rad); refused unless there are as many as the robot has joints.
  std::vector<double> position;
  // The message's count of pieces as sent; the array below is what arrived. The two differ only
  // when a sender builds a message by hand, which is refused rather than guessed at.
  int num_pieces = 0;
  std::vector<std::string> pieces;  // names of the held game pieces ([pieces.NAME] of the config)
  std::string scene_name;           // "" = the default scene
  double scene_offset_m = 0.0;      // within the scene's offset_range_m
};

struct ValidGoal {
  std::int64_t request_id = 0;
  planner::JointVector q;
  planner::HeldPieces pieces;
  int scene = 0;
  double scene_offset_m = 0.0;
};

// The pose a goal's pose_name names for its held pieces, or an error whose message lists the
// poses that set has. The daemon builds it from its configuration (daemon/io/named_poses.hpp);
// an empty one refuses every name.
using PoseLookup = std::function<planner::Result<planner::JointVector>(planner::HeldPieces, const std::string&)>;

// kInvalidInput for a joint count other than the robot's, non-finite values, bad piece lists,
// unknown pose names, unknown scenes and scene offsets outside the scene's range;
// kGoalOutOfRange outside the joint limits (a named pose is checked like sent values).
planner::Result<ValidGoal> validateGoal(const GoalRequest& goal, const planner::RobotModel& robot,
                                        const PoseLookup& poses = {});

}  // namespace cyber::daemon

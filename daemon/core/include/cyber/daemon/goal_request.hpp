#pragma once
// A goal as it arrives (ARM_GOAL fields) and its validation against the robot model. Every
// problem is a PlanError whose reason names the field, and joints by the config's names.

#include <cstdint>
#include <string>
#include <vector>

#include "cyber/planner.hpp"

namespace cyber::daemon {

// The most pieces a goal may name (arm_goal_t::MAX_PIECES; the planner's own limit).
inline constexpr int kMaxGoalPieces = planner::HeldPieces::kMaxPieces;

struct GoalRequest {
  std::int64_t request_id = 0;
  // Targets of joint 0 and joint 1 (config [[joints]] order), each in its joint's unit (m or rad).
  planner::JointVector position = planner::JointVector::Zero();
  // The message's count of pieces as sent; the array below is what arrived. The two differ only
  // when a sender builds a message by hand, which is refused rather than guessed at.
  int num_pieces = 0;
  std::vector<std::string> pieces;  // names of the held game pieces ([pieces.NAME] of the config)
  std::string scene_name;           // "" = the default scene
  double scene_offset_m = 0.0;      // within the scene's offset_range_m
};

struct ValidGoal {
  std::int64_t request_id = 0;
  planner::JointVector q = planner::JointVector::Zero();
  planner::HeldPieces pieces;
  int scene = 0;
  double scene_offset_m = 0.0;
};

// kInvalidInput for non-finite values, bad piece lists, unknown scenes and scene offsets outside
// the scene's range; kGoalOutOfRange outside the joint limits.
planner::Result<ValidGoal> validateGoal(const GoalRequest& goal, const planner::RobotModel& robot);

}  // namespace cyber::daemon

#pragma once
// A goal as it arrives (ARM_GOAL fields) and its validation against the robot model. Every
// problem is a PlanError whose reason names the field.

#include <cstdint>
#include <string>

#include "cyber/planner/result.hpp"
#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::daemon {

struct GoalRequest {
  std::int64_t request_id = 0;
  double elevator_m = 0.0;
  double arm_rad = 0.0;
  bool held_coral = false;
  bool held_algae = false;
  std::string scene_name;  // "" = the default scene
};

struct ValidGoal {
  std::int64_t request_id = 0;
  planner::JointVector q = planner::JointVector::Zero();
  planner::HeldPieces pieces;
  int scene = 0;
};

// kInvalidInput for non-finite values and unknown scenes, kGoalOutOfRange outside the joint limits.
planner::Result<ValidGoal> validateGoal(const GoalRequest& goal, const planner::RobotModel& robot);

}  // namespace cyber::daemon

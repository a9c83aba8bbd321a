#include "cyber/daemon/goal_request.hpp"

#include <cmath>
#include <optional>
#include <sstream>

namespace cyber::daemon {

namespace {

std::string describe(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::optional<std::string> checkJoint(const char* name, double value, const planner::JointRange& range,
                                      const char* unit) {
  if (value >= range.min && value <= range.max) return std::nullopt;
  std::ostringstream out;
  out << name << " = " << value << " " << unit << " is outside [" << range.min << ", " << range.max << "] " << unit;
  return out.str();
}

}  // namespace

planner::Result<ValidGoal> validateGoal(const GoalRequest& goal, const planner::RobotModel& robot) {
  using planner::PlanStatus;
  if (!std::isfinite(goal.elevator_m)) {
    return planner::Result<ValidGoal>::failure(PlanStatus::kInvalidInput,
                                               "elevator_m is not finite (" + describe(goal.elevator_m) + ")");
  }
  if (!std::isfinite(goal.arm_rad)) {
    return planner::Result<ValidGoal>::failure(PlanStatus::kInvalidInput,
                                               "arm_rad is not finite (" + describe(goal.arm_rad) + ")");
  }
  if (auto problem = checkJoint("elevator_m", goal.elevator_m, robot.elevator_range_m, "m")) {
    return planner::Result<ValidGoal>::failure(PlanStatus::kGoalOutOfRange, *problem);
  }
  if (auto problem = checkJoint("arm_rad", goal.arm_rad, robot.arm_range_rad, "rad")) {
    return planner::Result<ValidGoal>::failure(PlanStatus::kGoalOutOfRange, *problem);
  }
  ValidGoal valid;
  valid.request_id = goal.request_id;
  valid.q = planner::JointVector(goal.elevator_m, goal.arm_rad);
  valid.pieces = planner::HeldPieces{goal.held_coral, goal.held_algae};
  if (!goal.scene_name.empty()) {
    valid.scene = robot.sceneIndex(goal.scene_name);
    if (valid.scene < 0) {
      std::string known;
      for (const auto& scene : robot.scenes) known += (known.empty() ? "" : ", ") + scene.name;
      return planner::Result<ValidGoal>::failure(PlanStatus::kInvalidInput,
                                                 "unknown scene '" + goal.scene_name + "' (known: " + known + ")");
    }
  }
  return valid;
}

}  // namespace cyber::daemon

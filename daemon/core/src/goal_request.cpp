#include "cyber/daemon/goal_request.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <utility>

namespace cyber::daemon {

namespace {

std::optional<std::string> checkJoint(const char* name, double value, const planner::JointRange& range,
                                      const char* unit) {
  if (value >= range.min && value <= range.max) return std::nullopt;
  return fmt::format("{} = {:g} {} is outside [{:g}, {:g}] {}", name, value, unit, range.min, range.max, unit);
}

// Scene names are short words from the config; anything else is refused without being echoed.
// A NUL byte matters most: LCM sizes a string by its length but encodes it only up to the first
// NUL, so echoing one in ARM_PLAN_STATUS would send the uninitialised rest of the send buffer
// (found by tests/fuzz/lcm_decode; docs/operations.md, "Threat model").
constexpr std::size_t kMaxSceneNameLength = 64;

bool isSceneName(const std::string& name) {
  if (name.size() > kMaxSceneNameLength) return false;
  for (const char c : name) {
    if (c < 0x20 || c > 0x7e) return false;
  }
  return true;
}

}  // namespace

planner::Result<ValidGoal> validateGoal(const GoalRequest& goal, const planner::RobotModel& robot) {
  using planner::PlanStatus;
  if (!isSceneName(goal.scene_name)) {
    return planner::Result<ValidGoal>::failure(PlanStatus::kInvalidInput,
                                               "scene_name is not a name (" + std::to_string(goal.scene_name.size()) +
                                                   " bytes; at most " + std::to_string(kMaxSceneNameLength) +
                                                   " printable ASCII characters)");
  }
  if (!std::isfinite(goal.elevator_m)) {
    return planner::Result<ValidGoal>::failure(PlanStatus::kInvalidInput,
                                               fmt::format("elevator_m is not finite ({:g})", goal.elevator_m));
  }
  if (!std::isfinite(goal.arm_rad)) {
    return planner::Result<ValidGoal>::failure(PlanStatus::kInvalidInput,
                                               fmt::format("arm_rad is not finite ({:g})", goal.arm_rad));
  }
  if (auto problem = checkJoint("elevator_m", goal.elevator_m, robot.range(0), "m")) {
    return planner::Result<ValidGoal>::failure(PlanStatus::kGoalOutOfRange, *problem);
  }
  if (auto problem = checkJoint("arm_rad", goal.arm_rad, robot.range(1), "rad")) {
    return planner::Result<ValidGoal>::failure(PlanStatus::kGoalOutOfRange, *problem);
  }
  ValidGoal valid;
  valid.request_id = goal.request_id;
  valid.q = planner::JointVector(goal.elevator_m, goal.arm_rad);
  // The message's two held flags name the first configuration's pieces until ARM_GOAL carries
  // names (docs/lcm.md).
  for (const auto& [held, name] : {std::pair{goal.held_coral, "coral"}, std::pair{goal.held_algae, "algae"}}) {
    if (!held) continue;
    const int piece = robot.pieceIndex(name);
    if (piece < 0) {
      return planner::Result<ValidGoal>::failure(PlanStatus::kInvalidInput,
                                                 fmt::format("the robot has no game piece named {}", name));
    }
    valid.pieces = valid.pieces.with(piece);
  }
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

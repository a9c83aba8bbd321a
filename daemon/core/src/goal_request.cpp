#include "cyber/daemon/goal_request.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "cyber/planner.hpp"

namespace cyber::daemon {

namespace {

using planner::PlanStatus;
using Failure = planner::Result<ValidGoal>;

// Names are short words from the config; anything else is refused without being echoed.
// A NUL byte matters most: LCM sizes a string by its length but encodes it only up to the first
// NUL, so echoing one in ARM_PLAN_STATUS would send the uninitialised rest of the send buffer
// (found by tests/fuzz/lcm_decode; docs/operations.md, "Threat model").
constexpr std::size_t kMaxNameLength = 64;

bool isName(const std::string& name) {
  if (name.size() > kMaxNameLength) return false;
  for (const char c : name) {
    if (c < 0x20 || c > 0x7e) return false;
  }
  return true;
}

std::string notAName(const std::string& field, const std::string& name) {
  return fmt::format("{} is not a name ({} bytes; at most {} printable ASCII characters)", field, name.size(),
                     kMaxNameLength);
}

std::string joinedNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + name;
  return out.empty() ? "none" : out;
}

// The sent values as the robot's joint vector: exactly one per joint of the configuration.
planner::Result<planner::JointVector> sentPosition(const std::vector<double>& values,
                                                   const planner::RobotModel& robot) {
  if (values.size() != static_cast<size_t>(robot.jointCount())) {
    std::vector<std::string> names;
    for (const planner::ChainJoint& joint : robot.joints) names.push_back(joint.name);
    return planner::Result<planner::JointVector>::failure(
        PlanStatus::kInvalidInput, fmt::format("num_joints = {} but this robot has {} joints ({})", values.size(),
                                               robot.joints.size(), joinedNames(names)));
  }
  planner::JointVector q(static_cast<Eigen::Index>(values.size()));
  for (size_t j = 0; j < values.size(); ++j) q[static_cast<Eigen::Index>(j)] = values[j];
  return q;
}

// The target: the named pose of the held set, or the sent values.
planner::Result<planner::JointVector> targetOf(const GoalRequest& goal, const planner::RobotModel& robot,
                                               planner::HeldPieces held, const PoseLookup& poses) {
  if (goal.pose_name.empty()) return sentPosition(goal.position, robot);
  if (!isName(goal.pose_name)) {
    return planner::Result<planner::JointVector>::failure(PlanStatus::kInvalidInput,
                                                          notAName("pose_name", goal.pose_name));
  }
  if (!poses) {
    return planner::Result<planner::JointVector>::failure(
        PlanStatus::kInvalidInput, fmt::format("no pose \"{}\": this daemon has no named poses", goal.pose_name));
  }
  return poses(held, goal.pose_name);
}

std::optional<planner::PlanError> checkPosition(const planner::JointVector& q, const planner::RobotModel& robot) {
  for (int j = 0; j < static_cast<int>(robot.joints.size()); ++j) {
    const planner::ChainJoint& joint = robot.joints[static_cast<size_t>(j)];
    const char* unit = planner::unitName(joint.type);
    const double value = q[j];
    if (!std::isfinite(value)) {
      return planner::PlanError{PlanStatus::kInvalidInput,
                                fmt::format("position[{}] ({}) is not finite ({:g})", j, joint.name, value)};
    }
    if (value < joint.range.min || value > joint.range.max) {
      return planner::PlanError{PlanStatus::kGoalOutOfRange,
                                fmt::format("position[{}] ({}) = {:g} {} is outside [{:g}, {:g}] {}", j, joint.name,
                                            value, unit, joint.range.min, joint.range.max, unit)};
    }
  }
  return std::nullopt;
}

// The held set of the named pieces; each name once, each one of the config's.
std::optional<std::string> readPieces(const GoalRequest& goal, const planner::RobotModel& robot,
                                      planner::HeldPieces& held) {
  if (goal.num_pieces < 0 || goal.num_pieces > kMaxGoalPieces) {
    return fmt::format("num_pieces = {} is outside 0..{}", goal.num_pieces, kMaxGoalPieces);
  }
  if (goal.num_pieces != static_cast<int>(goal.pieces.size())) {
    return fmt::format("num_pieces = {} but {} piece names came", goal.num_pieces, goal.pieces.size());
  }
  std::vector<std::string> known;
  for (const auto& piece : robot.pieces) known.push_back(piece.name);
  for (size_t i = 0; i < goal.pieces.size(); ++i) {
    const std::string& name = goal.pieces[i];
    if (!isName(name)) return notAName(fmt::format("pieces[{}]", i), name);
    const int piece = robot.pieceIndex(name);
    if (piece < 0) {
      return fmt::format("unknown game piece '{}' in pieces[{}] (this robot's: {})", name, i, joinedNames(known));
    }
    if (held.holds(piece)) return fmt::format("game piece '{}' is named twice in pieces", name);
    held = held.with(piece);
  }
  return std::nullopt;
}

}  // namespace

planner::Result<ValidGoal> validateGoal(const GoalRequest& goal, const planner::RobotModel& robot,
                                        const PoseLookup& poses) {
  if (!isName(goal.scene_name))
    return Failure::failure(PlanStatus::kInvalidInput, notAName("scene_name", goal.scene_name));
  ValidGoal valid;
  valid.request_id = goal.request_id;
  // The pieces first: a pose name means a pose of the held set.
  if (auto problem = readPieces(goal, robot, valid.pieces)) {
    return Failure::failure(PlanStatus::kInvalidInput, *problem);
  }
  auto target = targetOf(goal, robot, valid.pieces, poses);
  if (!target) return Failure::failure(target.error().status, target.error().message);
  valid.q = target.value();
  if (auto problem = checkPosition(valid.q, robot)) return Failure::failure(problem->status, problem->message);
  if (!goal.scene_name.empty()) {
    valid.scene = robot.sceneIndex(goal.scene_name);
    if (valid.scene < 0) {
      std::vector<std::string> known;
      for (const auto& scene : robot.scenes) known.push_back(scene.name);
      return Failure::failure(PlanStatus::kInvalidInput,
                              "unknown scene '" + goal.scene_name + "' (known: " + joinedNames(known) + ")");
    }
  }
  const planner::Scene& scene = robot.scenes[static_cast<size_t>(valid.scene)];
  const double offset = goal.scene_offset_m;
  if (!std::isfinite(offset)) {
    return Failure::failure(PlanStatus::kInvalidInput, fmt::format("scene_offset_m is not finite ({:g})", offset));
  }
  if (!scene.offset_range_m.contains(offset)) {
    return Failure::failure(PlanStatus::kInvalidInput,
                            fmt::format("scene_offset_m = {:g} m is outside scene {}'s offset range [{:g}, {:g}] m",
                                        offset, scene.name, scene.offset_range_m.min, scene.offset_range_m.max));
  }
  valid.scene_offset_m = offset;
  return valid;
}

}  // namespace cyber::daemon

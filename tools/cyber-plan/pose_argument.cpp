#include "pose_argument.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace cyber::tools {

namespace {

// "elevator, arm": the joints in chain order, for messages about how many values a pose needs.
std::string jointList(const planner::RobotModel& robot) {
  std::string out;
  for (const planner::ChainJoint& joint : robot.joints) out.append(out.empty() ? "" : ", ").append(joint.name);
  return out;
}

std::string poseNames(const config::PoseSet& set) {
  std::string out;
  for (const config::NamedPose& pose : set.poses) out.append(out.empty() ? "" : ", ").append(pose.name);
  return out;
}

bool declares(const config::PoseSet& set, std::string_view name) {
  return std::any_of(set.poses.begin(), set.poses.end(), [&](const config::NamedPose& p) { return p.name == name; });
}

// The sets other than `held`'s that declare `name`, as "; it is a pose of \"algae\"", or "".
std::string elsewhere(const std::vector<config::PoseSet>& poses, planner::HeldPieces held, std::string_view name) {
  std::string sets;
  for (const config::PoseSet& set : poses) {
    if (set.pieces != held && declares(set, name))
      sets.append(sets.empty() ? "\"" : ", \"").append(set.name).append("\"");
  }
  return sets.empty() ? "" : "; it is a pose of " + sets;
}

}  // namespace

Result<PoseArgument, cli::ArgumentStatus> parsePoseArgument(std::string_view text, cli::NonFinite non_finite) {
  const bool numbers = text.find(',') != std::string_view::npos || cli::parseNumber(text, cli::NonFinite::kAccept);
  if (!text.empty() && !numbers) return PoseArgument{std::string(text), {}};
  PoseArgument pose;
  for (size_t from = 0;;) {
    const size_t comma = text.find(',', from);
    const auto value = cli::parseNumber(text.substr(from, comma - from), non_finite);  // npos: to the end
    if (!value) {
      return cli::badUsage(
          fmt::format("expects the joints' values in chain order separated by ',' ({}numbers) or a "
                      "pose name, got '{}'",
                      non_finite == cli::NonFinite::kReject ? "finite " : "", text));
    }
    pose.values.push_back(*value);
    if (comma == std::string_view::npos) return pose;
    from = comma + 1;
  }
}

Result<planner::JointVector, cli::ArgumentStatus> namedPose(const std::vector<config::PoseSet>& poses,
                                                            const planner::RobotModel& robot, planner::HeldPieces held,
                                                            const std::string& name) {
  const auto set = std::find_if(poses.begin(), poses.end(), [&](const config::PoseSet& s) { return s.pieces == held; });
  if (set == poses.end()) {
    return cli::badUsage(fmt::format("no pose \"{}\": the configuration names no poses for the held set \"{}\"{}", name,
                                     robot.pieceSetName(held), elsewhere(poses, held, name)));
  }
  for (const config::NamedPose& pose : set->poses) {
    if (pose.name == name) return pose.q;
  }
  return cli::badUsage(fmt::format("no pose \"{}\" for the held set \"{}\" (its poses: {}){}", name, set->name,
                                   poseNames(*set), elsewhere(poses, held, name)));
}

Result<planner::JointVector, cli::ArgumentStatus> resolvePose(const PoseArgument& pose, const config::Config& config,
                                                              planner::HeldPieces held) {
  if (!pose.name.empty()) return namedPose(config.poses, config.robot, held, pose.name);
  const planner::RobotModel& robot = config.robot;
  if (pose.values.size() != static_cast<size_t>(robot.jointCount())) {
    return cli::badUsage(fmt::format("expects {} values, one per joint ({}), got {}", robot.jointCount(),
                                     jointList(robot), pose.values.size()));
  }
  planner::JointVector q(robot.jointCount());
  for (size_t j = 0; j < pose.values.size(); ++j) q[static_cast<Eigen::Index>(j)] = pose.values[j];
  return q;
}

}  // namespace cyber::tools

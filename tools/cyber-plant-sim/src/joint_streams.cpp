#include "cyber/plant/joint_streams.hpp"

#include <fmt/format.h>

#include <iterator>

namespace cyber::plant {

std::optional<int> JointStreams::jointOf(std::uint8_t device) const {
  for (int j = 0; j < jointCount(); ++j) {
    if (devices_[j] == device) return j;
  }
  return std::nullopt;
}

JointStreams::Update JointStreams::onSetpoint(int joint, std::uint8_t sequence, bool moving) {
  const auto index = static_cast<std::size_t>(joint);
  Update update;
  auto& last = last_sequence_[index];
  update.sequence_gap = last && static_cast<std::uint8_t>(*last + 1) != sequence;
  if (update.sequence_gap) ++sequence_gaps_;
  last = sequence;
  update.first = setpoints_[index]++ == 0;
  joint_moving_[index] = moving;
  bool any_moving = false;
  for (int j = 0; j < jointCount(); ++j) any_moving = any_moving || joint_moving_[static_cast<std::size_t>(j)];
  if (moving && !moving_) {
    moving_ = true;
    ++motions_;
    update.motion_started = true;
  } else if (moving_ && !any_moving) {
    moving_ = false;
    update.came_to_rest = true;
  }
  return update;
}

std::string devicesText(const planner::PerJoint<std::uint8_t>& devices) {
  std::string out;
  for (int j = 0; j < devices.size(); ++j) {
    fmt::format_to(std::back_inserter(out), "{}joint {} device {}", j == 0 ? "" : ", ", j, devices[j]);
  }
  return out;
}

std::string positionsText(const planner::PerJoint<std::string>& names, const planner::PerJoint<std::string>& units,
                          const planner::JointVector& q) {
  std::string out;
  for (int j = 0; j < names.size(); ++j) {
    fmt::format_to(std::back_inserter(out), "{}{} {:.6f} {}", j == 0 ? "" : ", ", names[j], q[j], units[j]);
  }
  return out;
}

std::string setpointCountsText(const planner::PerJoint<std::string>& names, const JointStreams& streams) {
  std::string out;
  for (int j = 0; j < names.size(); ++j) {
    fmt::format_to(std::back_inserter(out), "{}{} {}", j == 0 ? "" : " ", names[j], streams.setpoints(j));
  }
  return out;
}

}  // namespace cyber::plant

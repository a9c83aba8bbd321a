#pragma once
// The setpoint streams cyber-plant-sim receives, one per joint of the config (docs/can-protocol.md:
// each joint's controller is a device number, config.daemon.devices.joints): which joint a
// frame's device drives, each stream's count and sequence gaps, and when the streams together
// start a motion or come to rest (fault_schedule.hpp: a motion starts with a frame carrying a
// non-zero velocity while every joint's latest frame carried none). Pure: no clock, no I/O.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "cyber/planner.hpp"
#include "cyber/plant/mechanism_plant.hpp"

namespace cyber::plant {

class JointStreams {
 public:
  // One device number per joint, chain order (distinct).
  explicit JointStreams(const planner::PerJoint<std::uint8_t>& devices) : devices_(devices) {}

  // What one setpoint frame changed.
  struct Update {
    bool first = false;           // the joint's first frame
    bool sequence_gap = false;    // its sequence byte did not follow the joint's previous one
    bool motion_started = false;  // the streams were at rest and this frame moves
    bool came_to_rest = false;    // the streams were moving and now every joint's latest frame is still
  };

  [[nodiscard]] int jointCount() const { return devices_.size(); }
  // The joint whose setpoints a device number carries; none for any other device.
  [[nodiscard]] std::optional<int> jointOf(std::uint8_t device) const;
  // A frame for `joint` with its sequence byte; `moving`: its velocity is non-zero.
  Update onSetpoint(int joint, std::uint8_t sequence, bool moving);

  [[nodiscard]] bool moving() const { return moving_; }
  [[nodiscard]] long setpoints(int joint) const { return setpoints_[static_cast<std::size_t>(joint)]; }
  [[nodiscard]] long sequenceGaps() const { return sequence_gaps_; }
  [[nodiscard]] int motions() const { return motions_; }

 private:
  planner::PerJoint<std::uint8_t> devices_;
  std::array<std::optional<std::uint8_t>, kMaxJoints> last_sequence_{};
  JointFlags joint_moving_{};  // the joint's latest frame has a velocity
  std::array<long, kMaxJoints> setpoints_{};
  long sequence_gaps_ = 0;
  bool moving_ = false;
  int motions_ = 0;
};

// The joints and their devices for the start-up line: "joint 0 device 1, joint 1 device 2".
std::string devicesText(const planner::PerJoint<std::uint8_t>& devices);

// The per-joint parts of the closing line, by the config's names (tests/hil/hil_lib.py reads the
// two-joint form): positions "elevator 0.500000 m, arm 1.570000 rad" and setpoint counts
// "elevator 120 arm 118".
std::string positionsText(const planner::PerJoint<std::string>& names, const planner::PerJoint<std::string>& units,
                          const planner::JointVector& q);
std::string setpointCountsText(const planner::PerJoint<std::string>& names, const JointStreams& streams);

}  // namespace cyber::plant

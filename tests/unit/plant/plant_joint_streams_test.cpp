// The setpoint streams of cyber-plant-sim per joint: device numbers, counts, sequence gaps, motions,
// and the per-joint text of its start-up and closing lines, for chains of one, two and three joints.

#include <gtest/gtest.h>

#include "cyber/plant/joint_streams.hpp"

namespace cyber::plant {
namespace {

TEST(JointStreams, EachDeviceDrivesItsOwnJoint) {
  const JointStreams three(planner::PerJoint<std::uint8_t>{4, 9, 2});
  EXPECT_EQ(three.jointCount(), 3);
  EXPECT_EQ(three.jointOf(4), 0);
  EXPECT_EQ(three.jointOf(9), 1);
  EXPECT_EQ(three.jointOf(2), 2);
  EXPECT_FALSE(three.jointOf(1));
  EXPECT_FALSE(three.jointOf(3));
  const JointStreams one(planner::PerJoint<std::uint8_t>{1});
  EXPECT_EQ(one.jointOf(1), 0);
  EXPECT_FALSE(one.jointOf(2));  // the device a second joint would have
}

TEST(JointStreams, CountsFramesAndSequenceGapsPerJoint) {
  JointStreams streams(planner::PerJoint<std::uint8_t>{1, 2, 3});
  EXPECT_TRUE(streams.onSetpoint(2, 200, false).first);
  EXPECT_FALSE(streams.onSetpoint(2, 201, false).first);
  EXPECT_TRUE(streams.onSetpoint(0, 7, false).first);  // each joint's own sequence
  EXPECT_FALSE(streams.onSetpoint(0, 8, false).sequence_gap);
  EXPECT_TRUE(streams.onSetpoint(2, 203, false).sequence_gap);
  EXPECT_FALSE(streams.onSetpoint(2, 204, false).sequence_gap);
  streams.onSetpoint(1, 255, false);
  EXPECT_FALSE(streams.onSetpoint(1, 0, false).sequence_gap);  // the byte wraps
  EXPECT_EQ(streams.setpoints(0), 2);
  EXPECT_EQ(streams.setpoints(1), 2);
  EXPECT_EQ(streams.setpoints(2), 4);
  EXPECT_EQ(streams.sequenceGaps(), 1);
}

// A motion starts with a moving frame of any joint while all were still, and ends only once the
// latest frame of every joint is still again.
TEST(JointStreams, AMotionLastsUntilEveryJointIsStill) {
  JointStreams streams(planner::PerJoint<std::uint8_t>{1, 2, 3});
  std::uint8_t sequence[3] = {0, 0, 0};
  const auto frame = [&](int joint, bool moving) { return streams.onSetpoint(joint, sequence[joint]++, moving); };
  EXPECT_FALSE(frame(0, false).motion_started);
  EXPECT_TRUE(frame(2, true).motion_started);  // the last joint alone starts it
  EXPECT_EQ(streams.motions(), 1);
  EXPECT_FALSE(frame(0, true).motion_started);
  EXPECT_FALSE(frame(2, false).came_to_rest);  // joint 0 still moves
  EXPECT_FALSE(frame(1, false).came_to_rest);
  EXPECT_TRUE(streams.moving());
  EXPECT_TRUE(frame(0, false).came_to_rest);
  EXPECT_FALSE(streams.moving());
  EXPECT_FALSE(frame(1, false).came_to_rest);
  EXPECT_TRUE(frame(1, true).motion_started);
  EXPECT_EQ(streams.motions(), 2);

  JointStreams one(planner::PerJoint<std::uint8_t>{5});
  EXPECT_TRUE(one.onSetpoint(0, 0, true).motion_started);
  EXPECT_TRUE(one.onSetpoint(0, 1, false).came_to_rest);
  EXPECT_EQ(one.motions(), 1);
}

// The two-joint form is what tests/hil/hil_lib.py reads from the closing line.
TEST(JointStreams, LineTextNamesEveryJoint) {
  EXPECT_EQ(devicesText(planner::PerJoint<std::uint8_t>{1, 2}), "joint 0 device 1, joint 1 device 2");
  EXPECT_EQ(devicesText(planner::PerJoint<std::uint8_t>{7}), "joint 0 device 7");
  EXPECT_EQ(devicesText(planner::PerJoint<std::uint8_t>{1, 2, 3}),
            "joint 0 device 1, joint 1 device 2, joint 2 device 3");

  const planner::PerJoint<std::string> names{"elevator", "arm"};
  JointStreams two(planner::PerJoint<std::uint8_t>{1, 2});
  for (std::uint8_t k = 0; k < 3; ++k) two.onSetpoint(0, k, false);
  two.onSetpoint(1, 0, false);
  EXPECT_EQ(positionsText(names, {"m", "rad"}, planner::JointVector{{0.5, 1.5708}}),
            "elevator 0.500000 m, arm 1.570800 rad");
  EXPECT_EQ(setpointCountsText(names, two), "elevator 3 arm 1");

  const planner::PerJoint<std::string> three{"elevator", "pivot", "wrist"};
  JointStreams streams(planner::PerJoint<std::uint8_t>{1, 2, 3});
  streams.onSetpoint(2, 0, false);
  EXPECT_EQ(positionsText(three, {"m", "rad", "rad"}, planner::JointVector{{0.05, 1.5708, -0.25}}),
            "elevator 0.050000 m, pivot 1.570800 rad, wrist -0.250000 rad");
  EXPECT_EQ(setpointCountsText(three, streams), "elevator 0 pivot 0 wrist 1");
  EXPECT_EQ(positionsText({"pivot"}, {"rad"}, planner::JointVector{{-0.72}}), "pivot -0.720000 rad");
}

}  // namespace
}  // namespace cyber::plant

#include "cyber/daemon/io/lcm_messages.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "cyber/lcmtypes/safe_decode.hpp"
#include "cyberplanner/arm_daemon_status_t.hpp"
#include "fake_trajectory.hpp"
#include "reference_model.hpp"

namespace cyber::daemon::io {
namespace {

// Encoded and decoded again, as a peer's goal arrives.
template <class Message>
Message roundTrip(const Message& message) {
  std::vector<std::uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
  EXPECT_EQ(message.encode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
  Message decoded{};
  EXPECT_EQ(lcmtypes::safeDecode(decoded, bytes.data(), static_cast<int>(bytes.size())),
            static_cast<int>(bytes.size()));
  return decoded;
}

TEST(LcmMessages, GoalFieldsSurviveTheWireAndAreCopied) {
  cyberplanner::arm_goal_t message{};
  message.request_id = -5;
  message.num_joints = 2;
  message.position = {1.25, 2.5};
  message.num_pieces = 2;
  message.pieces = {"algae", "coral"};
  message.scene_name = "reef";
  message.scene_offset_m = 0.125;
  const GoalRequest goal = goalFromMessage(roundTrip(message));
  EXPECT_EQ(goal.request_id, -5);
  EXPECT_EQ(goal.position, (std::vector<double>{1.25, 2.5}));
  EXPECT_EQ(goal.pose_name, "");
  EXPECT_EQ(goal.num_pieces, 2);
  EXPECT_EQ(goal.pieces, (std::vector<std::string>{"algae", "coral"}));
  EXPECT_EQ(goal.scene_name, "reef");
  EXPECT_EQ(goal.scene_offset_m, 0.125);
  // ... and validate to the pieces and the offset the planner is asked for.
  const auto valid = validateGoal(goal, cyber::test::referenceModel());
  ASSERT_TRUE(valid) << valid.error().message;
  EXPECT_EQ(valid.value().pieces, cyber::test::referencePieces("coral+algae"));
  EXPECT_EQ(valid.value().scene_offset_m, 0.125);
}

// A named goal may send no joint values (docs/lcm.md, "Named goals").
TEST(LcmMessages, ANamedGoalArrivesWithItsNameAndNoValues) {
  cyberplanner::arm_goal_t message{};
  message.request_id = 3;
  message.pose_name = "L3";
  const GoalRequest goal = goalFromMessage(roundTrip(message));
  EXPECT_EQ(goal.pose_name, "L3");
  EXPECT_TRUE(goal.position.empty());
}

TEST(LcmMessages, StateAndSetpointAndStatusRoundTrip) {
  cyberplanner::arm_state_t state{};
  state.num_joints = 2;
  state.position = {0.5, 0.0};
  state.velocity = {0.0, -0.25};
  state.num_pieces = 1;
  state.pieces = {"coral"};
  const auto state_back = roundTrip(state);
  EXPECT_EQ(state_back.position[0], 0.5);
  EXPECT_EQ(state_back.velocity[1], -0.25);
  EXPECT_EQ(state_back.pieces, std::vector<std::string>{"coral"});

  StreamSnapshot snapshot;
  snapshot.joints = {can::Setpoint{0.5, 0.25, 1.5, 3}, can::Setpoint{1.0, -0.5, -0.75, 4}};
  const auto setpoint = roundTrip(setpointMessage(snapshot, 2, 1));
  EXPECT_EQ(setpoint.num_joints, 2);
  EXPECT_EQ(setpoint.position[1], 1.0);
  EXPECT_EQ(setpoint.volts[0], 1.5);
  EXPECT_EQ(setpoint.sequence[1], 4);

  cyberplanner::arm_daemon_status_t status{};
  status.num_joints = 2;
  status.joint_names = {"elevator", "arm"};
  status.joint_units = {"m", "rad"};
  const auto status_back = roundTrip(status);
  EXPECT_EQ(status_back.joint_names[1], "arm");
  EXPECT_EQ(status_back.joint_units[0], "m");
}

TEST(LcmMessages, CancelsTakeTheRequestAndAKnownAction) {
  cyberplanner::arm_cancel_t message{};
  message.request_id = 42;
  message.action = cyberplanner::arm_cancel_t::ACTION_HOLD;
  ASSERT_TRUE(cancelFromMessage(message).has_value());
  EXPECT_EQ(cancelFromMessage(message)->request_id, 42);
  EXPECT_EQ(cancelFromMessage(message)->action, CancelAction::kHold);
  message.request_id = -1;
  message.action = cyberplanner::arm_cancel_t::ACTION_RELEASE;
  EXPECT_EQ(cancelFromMessage(message)->request_id, CancelRequest::kActive);
  EXPECT_EQ(cancelFromMessage(message)->action, CancelAction::kRelease);
  message.action = 2;
  EXPECT_FALSE(cancelFromMessage(message).has_value());
}

TEST(LcmMessages, StatesMustBeFiniteAndNearTheJointRanges) {
  const auto& robot = cyber::test::referenceModel();
  cyberplanner::arm_state_t message{};
  message.num_joints = 2;
  message.position = {0.5, 1.0};
  message.velocity = {0.1, -0.2};
  auto state = stateFromMessage(message, robot);
  ASSERT_TRUE(state);
  EXPECT_EQ(state->q, (JointVector{{0.5, 1.0}}));
  EXPECT_EQ(state->qdot, (JointVector{{0.1, -0.2}}));
  message.position[0] = -0.3;  // a little below the limit: still the mechanism's position
  EXPECT_TRUE(stateFromMessage(message, robot));
  message.position[0] = -0.6;
  EXPECT_FALSE(stateFromMessage(message, robot));
  message.position[0] = 0.5;
  message.velocity[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(stateFromMessage(message, robot));
  message.velocity[1] = 0.0;
  message.position[1] = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(stateFromMessage(message, robot));
}

// A state of another robot's joints is not read as this one's, nor past its arrays.
TEST(LcmMessages, StatesMustHaveTheRobotsJointCount) {
  const auto& robot = cyber::test::referenceModel();
  cyberplanner::arm_state_t message{};
  message.num_joints = 3;
  message.position = {0.5, 1.0, 0.0};
  message.velocity = {0.0, 0.0, 0.0};
  EXPECT_FALSE(stateFromMessage(roundTrip(message), robot));
  message.num_joints = 1;
  message.position = {0.5};
  message.velocity = {0.0};
  EXPECT_FALSE(stateFromMessage(roundTrip(message), robot));
  message.num_joints = 2;  // a count the arrays do not have, as a hand-built message might
  EXPECT_FALSE(stateFromMessage(message, robot));
  message.position = {0.5, 1.0};
  message.velocity = {0.0, 0.0};
  EXPECT_TRUE(stateFromMessage(message, robot));
}

TEST(LcmMessages, StatusCarriesStatusReasonTimesAndDuration) {
  StatusUpdate update;
  update.request_id = 9;
  update.status = GoalStatus::kFailed;
  update.reason = "no path: blocked";
  update.times_ms = StageTimesMs{1, 2, 3, 4, 10};
  update.duration_s = 1.5;
  const auto message = statusMessage(update, 123);
  EXPECT_EQ(message.utime, 123);
  EXPECT_EQ(message.request_id, 9);
  EXPECT_EQ(message.status, cyberplanner::arm_plan_status_t::STATUS_FAILED);
  EXPECT_EQ(message.reason, "no path: blocked");
  EXPECT_EQ(message.search_ms, 2);
  EXPECT_EQ(message.total_ms, 10);
  EXPECT_EQ(message.duration_s, 1.5);
  // Every GoalStatus maps to the constant of the same name.
  EXPECT_EQ(static_cast<int>(GoalStatus::kAccepted), cyberplanner::arm_plan_status_t::STATUS_ACCEPTED);
  EXPECT_EQ(static_cast<int>(GoalStatus::kPlanning), cyberplanner::arm_plan_status_t::STATUS_PLANNING);
  EXPECT_EQ(static_cast<int>(GoalStatus::kExecuting), cyberplanner::arm_plan_status_t::STATUS_EXECUTING);
  EXPECT_EQ(static_cast<int>(GoalStatus::kDone), cyberplanner::arm_plan_status_t::STATUS_DONE);
  EXPECT_EQ(static_cast<int>(GoalStatus::kRejected), cyberplanner::arm_plan_status_t::STATUS_REJECTED);
  EXPECT_EQ(static_cast<int>(GoalStatus::kCancelled), cyberplanner::arm_plan_status_t::STATUS_CANCELLED);
}

TEST(LcmMessages, TrajectoryIsSampledAtTheStepAndCoversTheWholeMotion) {
  const auto& robot = cyber::test::referenceModel();
  auto trajectory =
      daemon::test::makeHermite(JointVector{{0.1, 1.0}}, JointVector::Zero(2), JointVector{{1.5, 2.5}}, 1.234, robot);
  const auto message = trajectoryMessage(4, *trajectory, 2, 1000, 0.01, 2000);
  EXPECT_EQ(message.request_id, 4);
  EXPECT_EQ(message.start_utime, 1000);
  EXPECT_DOUBLE_EQ(message.dt_s, 0.01);
  EXPECT_EQ(message.num_joints, 2);
  EXPECT_EQ(message.num_samples, 125);  // 0 .. 1.23 s, then the end at 1.234 s
  ASSERT_EQ(message.t_s.size(), 125u);
  ASSERT_EQ(message.volts.size(), 2u);
  EXPECT_EQ(message.volts[1].size(), 125u);
  EXPECT_DOUBLE_EQ(message.t_s[123], 1.23);
  // The last sample is the rest state the motion ends in.
  EXPECT_EQ(message.t_s.back(), 1.234);
  EXPECT_DOUBLE_EQ(message.position[0].back(), 1.5);
  EXPECT_DOUBLE_EQ(message.position[1].back(), 2.5);
  EXPECT_EQ(message.velocity[0].back(), 0.0);
  EXPECT_EQ(message.velocity[1].back(), 0.0);
  EXPECT_DOUBLE_EQ(message.t_s[10], 0.1);
  const JointSetpoints s = trajectory->at(0.1);
  EXPECT_EQ(message.position[0][10], s.position[0]);
  EXPECT_EQ(message.velocity[1][10], s.velocity[1]);
  EXPECT_EQ(message.volts[0][10], s.volts[0]);
  EXPECT_EQ(message.position[0][0], 0.1);
  // Encodes and decodes whole: both rows are num_samples long.
  const auto back = roundTrip(message);
  EXPECT_EQ(back.position[1][10], message.position[1][10]);
}

TEST(LcmMessages, LongTrajectoriesAreCappedAtMaxSamplesAndStayUnder60kB) {
  const auto& robot = cyber::test::referenceModel();
  for (double duration : {9.98, 9.99, 10.0, 33.3, 120.0}) {
    auto trajectory = daemon::test::makeHermite(JointVector{{0.1, 1.0}}, JointVector::Zero(2), JointVector{{1.5, 2.5}},
                                                duration, robot);
    const auto message = trajectoryMessage(1, *trajectory, 2, 0, 0.01, 0);
    EXPECT_LE(message.num_samples, cyberplanner::arm_trajectory_t::MAX_SAMPLES) << duration;
    EXPECT_GE(message.dt_s, 0.01);
    // The last sample is the end of the motion, and the others are on the step.
    EXPECT_EQ(message.t_s.back(), duration) << duration;
    EXPECT_NEAR(message.t_s[message.t_s.size() - 2], (message.num_samples - 2) * message.dt_s, 1e-9) << duration;
    EXPECT_LE(message.t_s.back() - message.t_s[message.t_s.size() - 2], message.dt_s + 1e-9) << duration;
    EXPECT_LT(message.getEncodedSize(), 60000);
  }
  EXPECT_EQ(maxTrajectorySamples(2), cyberplanner::arm_trajectory_t::MAX_SAMPLES);
  auto still =
      daemon::test::makeHermite(JointVector{{0.1, 1.0}}, JointVector::Zero(2), JointVector{{0.1, 1.0}}, 0.0, robot);
  EXPECT_EQ(trajectoryMessage(1, *still, 2, 0, 0.01, 0).num_samples, 1);
}

// More joints, fewer samples: a full message of MAX_JOINTS joints stays under 60 kB too, and one
// more sample would not.
TEST(LcmMessages, TrajectorySamplesShrinkWithTheJointCountToStayUnder60kB) {
  for (int joints = 1; joints <= cyberplanner::arm_trajectory_t::MAX_JOINTS; ++joints) {
    const int samples = maxTrajectorySamples(joints);
    cyberplanner::arm_trajectory_t message{};
    message.num_joints = static_cast<std::int8_t>(joints);
    message.num_samples = samples;
    message.t_s.assign(static_cast<size_t>(samples), 0.0);
    for (auto* table : {&message.position, &message.velocity, &message.volts}) {
      table->assign(static_cast<size_t>(joints), std::vector<double>(static_cast<size_t>(samples)));
    }
    EXPECT_LT(message.getEncodedSize(), 60000) << joints;
    if (samples < cyberplanner::arm_trajectory_t::MAX_SAMPLES) {
      EXPECT_GE(message.getEncodedSize() + 8 * (1 + 3 * joints), 60000) << joints;
    }
  }
  EXPECT_EQ(maxTrajectorySamples(4), 576);
}

TEST(LcmMessages, SetpointEchoesTheWireValues) {
  StreamSnapshot snapshot;
  snapshot.mode = StreamMode::kMoving;
  snapshot.request_id = 12;
  snapshot.segment_time_s = 0.25;
  snapshot.joints = {can::Setpoint{0.12345, 0.5, 1.2, 7}, can::Setpoint{2.0, -1.0, 0.3, 9}};
  const auto message = setpointMessage(snapshot, 2, 55);
  EXPECT_EQ(message.mode, cyberplanner::arm_setpoint_t::MODE_MOVING);
  EXPECT_EQ(message.request_id, 12);
  EXPECT_EQ(message.trajectory_t_s, 0.25);
  EXPECT_EQ(message.position[0], 0.12345);
  EXPECT_EQ(message.velocity[1], -1.0);
  EXPECT_EQ(message.sequence[0], 7);
  EXPECT_EQ(message.sequence[1], 9);
  EXPECT_EQ(message.num_joints, 2);
  ASSERT_EQ(message.volts.size(), 2u);
  snapshot.mode = StreamMode::kHolding;
  EXPECT_EQ(setpointMessage(snapshot, 2, 0).trajectory_t_s, 0.0);
}

}  // namespace
}  // namespace cyber::daemon::io

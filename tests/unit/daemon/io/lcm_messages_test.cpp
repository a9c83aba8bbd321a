#include "cyber/daemon/io/lcm_messages.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "fake_trajectory.hpp"
#include "reference_model.hpp"

namespace cyber::daemon::io {
namespace {

TEST(LcmMessages, GoalFieldsAreCopied) {
  cyberplanner::arm_goal_t message{};
  message.request_id = -5;
  message.elevator_m = 1.25;
  message.arm_rad = 2.5;
  message.held_coral = 1;
  message.held_algae = 0;
  message.scene_name = "open";
  const GoalRequest goal = goalFromMessage(message);
  EXPECT_EQ(goal.request_id, -5);
  EXPECT_EQ(goal.elevator_m, 1.25);
  EXPECT_EQ(goal.arm_rad, 2.5);
  EXPECT_TRUE(goal.held_coral);
  EXPECT_FALSE(goal.held_algae);
  EXPECT_EQ(goal.scene_name, "open");
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
  message.elevator_m = 0.5;
  message.arm_rad = 1.0;
  message.elevator_mps = 0.1;
  message.arm_radps = -0.2;
  auto state = stateFromMessage(message, robot);
  ASSERT_TRUE(state);
  EXPECT_EQ(state->q, JointVector(0.5, 1.0));
  EXPECT_EQ(state->qdot, JointVector(0.1, -0.2));
  message.elevator_m = -0.3;  // a little below the limit: still the mechanism's position
  EXPECT_TRUE(stateFromMessage(message, robot));
  message.elevator_m = -0.6;
  EXPECT_FALSE(stateFromMessage(message, robot));
  message.elevator_m = 0.5;
  message.arm_radps = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(stateFromMessage(message, robot));
  message.arm_radps = 0.0;
  message.arm_rad = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(stateFromMessage(message, robot));
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
      daemon::test::makeHermite(JointVector(0.1, 1.0), JointVector::Zero(), JointVector(1.5, 2.5), 1.234, robot);
  const auto message = trajectoryMessage(4, *trajectory, 1000, 0.01, 2000);
  EXPECT_EQ(message.request_id, 4);
  EXPECT_EQ(message.start_utime, 1000);
  EXPECT_DOUBLE_EQ(message.dt_s, 0.01);
  EXPECT_EQ(message.num_samples, 125);  // 0 .. 1.23 s, then the end at 1.234 s
  ASSERT_EQ(message.t_s.size(), 125u);
  EXPECT_EQ(message.arm_volts.size(), 125u);
  EXPECT_DOUBLE_EQ(message.t_s[123], 1.23);
  // The last sample is the rest state the motion ends in.
  EXPECT_EQ(message.t_s.back(), 1.234);
  EXPECT_DOUBLE_EQ(message.elevator_m.back(), 1.5);
  EXPECT_DOUBLE_EQ(message.arm_rad.back(), 2.5);
  EXPECT_EQ(message.elevator_mps.back(), 0.0);
  EXPECT_EQ(message.arm_radps.back(), 0.0);
  EXPECT_DOUBLE_EQ(message.t_s[10], 0.1);
  const JointSetpoints s = trajectory->at(0.1);
  EXPECT_EQ(message.elevator_m[10], s.position[0]);
  EXPECT_EQ(message.arm_radps[10], s.velocity[1]);
  EXPECT_EQ(message.elevator_volts[10], s.volts[0]);
  EXPECT_EQ(message.elevator_m[0], 0.1);
}

TEST(LcmMessages, LongTrajectoriesAreCappedAtMaxSamplesAndStayUnder60kB) {
  const auto& robot = cyber::test::referenceModel();
  for (double duration : {9.98, 9.99, 10.0, 33.3, 120.0}) {
    auto trajectory =
        daemon::test::makeHermite(JointVector(0.1, 1.0), JointVector::Zero(), JointVector(1.5, 2.5), duration, robot);
    const auto message = trajectoryMessage(1, *trajectory, 0, 0.01, 0);
    EXPECT_LE(message.num_samples, cyberplanner::arm_trajectory_t::MAX_SAMPLES) << duration;
    EXPECT_GE(message.dt_s, 0.01);
    // The last sample is the end of the motion, and the others are on the step.
    EXPECT_EQ(message.t_s.back(), duration) << duration;
    EXPECT_NEAR(message.t_s[message.t_s.size() - 2], (message.num_samples - 2) * message.dt_s, 1e-9) << duration;
    EXPECT_LE(message.t_s.back() - message.t_s[message.t_s.size() - 2], message.dt_s + 1e-9) << duration;
    EXPECT_LT(message.getEncodedSize(), 60000);
  }
  auto still = daemon::test::makeHermite(JointVector(0.1, 1.0), JointVector::Zero(), JointVector(0.1, 1.0), 0.0, robot);
  EXPECT_EQ(trajectoryMessage(1, *still, 0, 0.01, 0).num_samples, 1);
}

TEST(LcmMessages, SetpointEchoesTheWireValues) {
  StreamSnapshot snapshot;
  snapshot.mode = StreamMode::kMoving;
  snapshot.request_id = 12;
  snapshot.segment_time_s = 0.25;
  snapshot.elevator = can::Setpoint{0.12345, 0.5, 1.2, 7};
  snapshot.arm = can::Setpoint{2.0, -1.0, 0.3, 9};
  const auto message = setpointMessage(snapshot, 55);
  EXPECT_EQ(message.mode, cyberplanner::arm_setpoint_t::MODE_MOVING);
  EXPECT_EQ(message.request_id, 12);
  EXPECT_EQ(message.trajectory_t_s, 0.25);
  EXPECT_EQ(message.elevator_m, 0.12345);
  EXPECT_EQ(message.arm_radps, -1.0);
  EXPECT_EQ(message.elevator_sequence, 7);
  EXPECT_EQ(message.arm_sequence, 9);
  snapshot.mode = StreamMode::kHolding;
  EXPECT_EQ(setpointMessage(snapshot, 0).trajectory_t_s, 0.0);
}

}  // namespace
}  // namespace cyber::daemon::io

#include "cyber/daemon/motion_gate.hpp"

#include <gtest/gtest.h>

namespace cyber::daemon {
namespace {

constexpr MonoNs kMs = 1'000'000;

GateSettings enabledGate() {
  GateSettings settings;
  settings.require_robot_enabled = true;
  settings.heartbeat_timeout_s = 0.1;
  settings.state_timeout_s = 0.25;
  return settings;
}

RobotInputs freshInputs(MonoNs now) {
  RobotInputs inputs;
  inputs.state_ns = now;
  inputs.heartbeat_ns = now;
  inputs.heartbeat_watchdog = true;
  return inputs;
}

TEST(MotionGate, OpenWithFreshStateAndEnabledHeartbeat) {
  const MonoNs now = 1000 * kMs;
  EXPECT_TRUE(evaluateGate(freshInputs(now), now, enabledGate()).open());
}

TEST(MotionGate, ClosedBeforeAnyState) {
  RobotInputs inputs = freshInputs(0);
  inputs.state_ns = kNever;
  EXPECT_EQ(evaluateGate(inputs, 0, enabledGate()).reason, GateReason::kNoState);
}

TEST(MotionGate, StateOlderThanItsTimeoutIsStale) {
  const MonoNs now = 1000 * kMs;
  RobotInputs inputs = freshInputs(now);
  inputs.state_ns = now - 250 * kMs;
  EXPECT_TRUE(evaluateGate(inputs, now, enabledGate()).open());
  inputs.state_ns = now - 251 * kMs;
  EXPECT_EQ(evaluateGate(inputs, now, enabledGate()).reason, GateReason::kStateStale);
}

TEST(MotionGate, HeartbeatTimesOutAfter100Ms) {
  const MonoNs now = 1000 * kMs;
  RobotInputs inputs = freshInputs(now);
  inputs.heartbeat_ns = now - 99 * kMs;
  EXPECT_TRUE(evaluateGate(inputs, now, enabledGate()).open());
  inputs.heartbeat_ns = now - 100 * kMs;
  EXPECT_EQ(evaluateGate(inputs, now, enabledGate()).reason, GateReason::kNoHeartbeat);
  inputs.heartbeat_ns = kNever;
  EXPECT_EQ(evaluateGate(inputs, now, enabledGate()).reason, GateReason::kNoHeartbeat);
}

TEST(MotionGate, HeartbeatWithoutWatchdogBitIsDisabled) {
  const MonoNs now = 1000 * kMs;
  RobotInputs inputs = freshInputs(now);
  inputs.heartbeat_watchdog = false;
  EXPECT_EQ(evaluateGate(inputs, now, enabledGate()).reason, GateReason::kRobotDisabled);
}

// Systemcore's FTC motor override (docs/can-protocol.md, "Robot heartbeat"): a hardware client
// may have the watchdog bit set for its motors while the robot program is disabled.
TEST(MotionGate, MotorOverrideClosesEvenWithTheWatchdogBit) {
  const MonoNs now = 1000 * kMs;
  RobotInputs inputs = freshInputs(now);
  inputs.heartbeat_motor_override = true;
  EXPECT_EQ(evaluateGate(inputs, now, enabledGate()).reason, GateReason::kMotorOverride);
  inputs.heartbeat_watchdog = false;
  EXPECT_EQ(evaluateGate(inputs, now, enabledGate()).reason, GateReason::kMotorOverride);
  EXPECT_TRUE(isRobotDisabledReason(GateReason::kMotorOverride));
  EXPECT_FALSE(toString(GateReason::kMotorOverride).empty());
  // A broadcast disable is not lifted by a heartbeat with the override.
  inputs.heartbeat_watchdog = true;
  inputs.broadcast_disable_ns = now - 10 * kMs;
  EXPECT_EQ(evaluateGate(inputs, now, enabledGate()).reason, GateReason::kMotorOverride);
  inputs.heartbeat_motor_override = false;
  EXPECT_TRUE(evaluateGate(inputs, now, enabledGate()).open());
}

TEST(MotionGate, BroadcastDisableHoldsUntilALaterEnabledHeartbeat) {
  const MonoNs now = 1000 * kMs;
  RobotInputs inputs = freshInputs(now);
  inputs.broadcast_disable_ns = now;  // same instant as the heartbeat: not lifted by it
  EXPECT_EQ(evaluateGate(inputs, now, enabledGate()).reason, GateReason::kBroadcastDisable);
  // Long after, still closed while no new heartbeat came (and then the heartbeat times out).
  EXPECT_EQ(evaluateGate(inputs, now + 50 * kMs, enabledGate()).reason, GateReason::kBroadcastDisable);
  inputs.heartbeat_ns = now + 20 * kMs;
  inputs.state_ns = now + 20 * kMs;
  EXPECT_TRUE(evaluateGate(inputs, now + 20 * kMs, enabledGate()).open());
}

TEST(MotionGate, BroadcastDisableWithoutTheGateHoldsForTheHeartbeatTimeout) {
  GateSettings bench = enabledGate();
  bench.require_robot_enabled = false;
  const MonoNs now = 1000 * kMs;
  RobotInputs inputs;
  inputs.state_ns = now;
  EXPECT_TRUE(evaluateGate(inputs, now, bench).open());  // no heartbeat needed on the bench
  inputs.broadcast_disable_ns = now;
  EXPECT_EQ(evaluateGate(inputs, now, bench).reason, GateReason::kBroadcastDisable);
  inputs.state_ns = now + 99 * kMs;
  EXPECT_EQ(evaluateGate(inputs, now + 99 * kMs, bench).reason, GateReason::kBroadcastDisable);
  inputs.state_ns = now + 100 * kMs;
  EXPECT_TRUE(evaluateGate(inputs, now + 100 * kMs, bench).open());
}

TEST(MotionGate, RobotReasonsComeBeforeStateReasons) {
  RobotInputs inputs;  // nothing at all
  EXPECT_EQ(evaluateGate(inputs, 0, enabledGate()).reason, GateReason::kNoHeartbeat);
  EXPECT_TRUE(isRobotDisabledReason(GateReason::kNoHeartbeat));
  EXPECT_TRUE(isRobotDisabledReason(GateReason::kBroadcastDisable));
  EXPECT_FALSE(isRobotDisabledReason(GateReason::kStateStale));
  EXPECT_FALSE(isRobotDisabledReason(GateReason::kNoState));
}

TEST(MotionGate, AReleaseClosesItOnlyWhenNothingElseDoes) {
  RobotInputs inputs;
  inputs.release_generation = 1;  // odd: released
  EXPECT_EQ(evaluateGate(inputs, 0, enabledGate()).reason, GateReason::kNoHeartbeat);
  inputs.heartbeat_ns = 0;
  inputs.heartbeat_watchdog = true;
  EXPECT_EQ(evaluateGate(inputs, 0, enabledGate()).reason, GateReason::kNoState);
  inputs.state_ns = 0;
  EXPECT_EQ(evaluateGate(inputs, 0, enabledGate()).reason, GateReason::kReleased);
  EXPECT_FALSE(isRobotDisabledReason(GateReason::kReleased));
  inputs.release_generation = 2;  // even: the release has ended
  EXPECT_TRUE(evaluateGate(inputs, 0, enabledGate()).open());
}

}  // namespace
}  // namespace cyber::daemon

#include "cyber/daemon/streamer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "fake_trajectory.hpp"
#include "reference_model.hpp"
#include "splice_into.hpp"

namespace cyber::daemon {
namespace {

using test::makeHermite;
constexpr MonoNs kMs = 1'000'000;
constexpr MonoNs kPeriod = 5 * kMs;

class StreamerTest : public ::testing::Test {
 protected:
  StreamerTest() : streamer(HoldModel(robot), settings()) {}

  static StreamerSettings settings() {
    StreamerSettings s;
    s.gate.require_robot_enabled = true;
    return s;
  }

  // Fresh state and an enabled heartbeat at `now`.
  void feed(const JointVector& measured) {
    inputs.state_ns = now;
    inputs.measured_q = measured;
    inputs.heartbeat_ns = now;
    inputs.heartbeat_watchdog = true;
  }

  TickOutput tick(Program* offered = nullptr, bool stop = false) {
    TickOutput out;
    streamer.tick(now, inputs, offered, stop, out);
    for (int i = 0; i < out.retired_count; ++i) delete out.retired[static_cast<size_t>(i)];
    for (int i = 0; i < out.event_count; ++i) events.push_back(out.events[static_cast<size_t>(i)]);
    now += kPeriod;
    return out;
  }

  // The latest event stopped request `id` because of `reason`.
  void expectStopped(std::int64_t id, GateReason reason) {
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(events.back().kind, StreamEventKind::kStopped);
    EXPECT_EQ(events.back().request_id, id);
    EXPECT_EQ(events.back().gate_reason, reason);
  }

  // (Re-)enabled with the mechanism at `measured`: the next tick holds it, not the last command.
  TickOutput expectEnabledHoldAt(const JointVector& measured) {
    feed(measured);
    const TickOutput out = tick();
    EXPECT_TRUE(out.send_setpoints);
    EXPECT_EQ(out.mode, StreamMode::kHolding);
    EXPECT_EQ(out.setpoints.position, measured);
    EXPECT_EQ(out.setpoints.velocity, JointVector::Zero(2));
    EXPECT_EQ(events.back().kind, StreamEventKind::kHolding);
    EXPECT_EQ(events.back().hold_cause, HoldCause::kEnabled);
    return out;
  }

  std::vector<StreamEventKind> kinds() const {
    std::vector<StreamEventKind> k;
    for (const auto& e : events) k.push_back(e.kind);
    return k;
  }

  // Enabled and holding at `from`, then request 1 moving to `to` over 2 s.
  void holdThenMove(const JointVector& from, const JointVector& to) {
    feed(from);
    tick();
    tick(moveFromRest(1, 1, from, to, 2.0));
  }

  // A program moving from the streamer's hold at `from` to `to`, based on its current epoch.
  Program* moveFromRest(std::int64_t id, std::uint64_t program_id, JointVector from, JointVector to,
                        double duration_s) {
    auto* p = new Program();
    std::vector<std::int64_t> dropped;
    Program base = Program::holdAt(streamer.epoch(), from);
    EXPECT_TRUE(test::spliceInto(
        base, {now, Segment{makeHermite(from, JointVector::Zero(2), to, duration_s, robot), id, 0}, true, program_id},
        *p, dropped));
    return p;
  }

  const planner::RobotModel& robot = cyber::test::referenceModel();
  Streamer streamer;
  RobotInputs inputs;
  MonoNs now = 1000 * kMs;
  std::vector<StreamEvent> events;
};

TEST_F(StreamerTest, StreamsNothingBeforeAnyState) {
  inputs.heartbeat_ns = now;
  inputs.heartbeat_watchdog = true;
  const TickOutput out = tick();
  EXPECT_FALSE(out.send_setpoints);
  EXPECT_EQ(out.mode, StreamMode::kNoState);
  EXPECT_EQ(out.gate_reason, GateReason::kNoState);
  EXPECT_TRUE(events.empty());
}

TEST_F(StreamerTest, FirstFreshStateHoldsTheMeasuredPositionWithGravityFeedforward) {
  const JointVector measured{{0.7, 0.9}};
  const TickOutput out = expectEnabledHoldAt(measured);
  EXPECT_DOUBLE_EQ(out.setpoints.volts[0], robot.drive(0).kG_volts);
  EXPECT_DOUBLE_EQ(out.setpoints.volts[1], robot.drive(1).kG_volts * std::cos(0.9));
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, StreamEventKind::kHolding);
  EXPECT_EQ(events[0].hold_cause, HoldCause::kEnabled);
  EXPECT_EQ(events[0].position, measured);
}

TEST_F(StreamerTest, RunsAProgramFromRestToItsEndAndHoldsThere) {
  const JointVector a{{0.2, 1.0}}, b{{1.0, 2.0}};
  feed(a);
  tick();
  Program* p = moveFromRest(11, 1, a, b, 0.5);
  feed(a);
  TickOutput first = tick(p);
  EXPECT_EQ(first.mode, StreamMode::kMoving);
  EXPECT_EQ(first.request_id, 11);
  EXPECT_EQ(first.setpoints.position, a);  // sample 0 of the new plan: no jump
  for (int i = 0; i < 105; ++i) {
    feed(a);
    tick();
  }
  const TickOutput last = tick();
  EXPECT_EQ(last.mode, StreamMode::kHolding);
  EXPECT_TRUE(last.setpoints.position.isApprox(b));
  EXPECT_EQ(last.setpoints.velocity, JointVector::Zero(2));
  EXPECT_DOUBLE_EQ(last.setpoints.volts[1], robot.drive(1).kG_volts * std::cos(last.setpoints.position[1]));
  EXPECT_EQ(last.request_id, 11);  // the held target still belongs to request 11
  EXPECT_EQ(kinds(), (std::vector<StreamEventKind>{StreamEventKind::kHolding, StreamEventKind::kAdopted,
                                                   StreamEventKind::kExecuting, StreamEventKind::kDone}));
}

TEST_F(StreamerTest, RejectsAFixedSpliceWhoseTimeWasAlreadyStreamed) {
  const JointVector a{{0.2, 1.0}}, b{{1.0, 2.0}};
  feed(a);
  tick();
  Program* p = moveFromRest(1, 1, a, b, 1.0);
  tick(p);
  const MonoNs streamed = now - kPeriod;  // the time sampled by the last tick
  auto* late = new Program();
  std::vector<std::int64_t> dropped;
  Program running = *p;
  ASSERT_TRUE(test::spliceInto(
      running, {now, Segment{makeHermite(a, JointVector::Zero(2), b, 1.0, robot), 2, streamed}, false, 2}, *late,
      dropped));
  feed(a);
  tick(late);
  ASSERT_EQ(events.back().kind, StreamEventKind::kRejected);
  EXPECT_EQ(events.back().program_id, 2u);
  EXPECT_EQ(events.back().reject_reason, RejectReason::kLate);
}

TEST_F(StreamerTest, RejectsAProgramBuiltOnAnotherBase) {
  const JointVector a{{0.2, 1.0}}, b{{1.0, 2.0}};
  feed(a);
  tick();
  Program* p = moveFromRest(1, 1, a, b, 1.0);
  p->base_id = 77;
  feed(a);
  tick(p);
  ASSERT_EQ(events.back().kind, StreamEventKind::kRejected);
  EXPECT_EQ(events.back().reject_reason, RejectReason::kStaleBase);
}

TEST_F(StreamerTest, HeartbeatTimeoutStopsMotionAndReEnableHoldsTheMeasuredPosition) {
  const JointVector a{{0.2, 1.0}}, b{{1.6, 3.0}};
  holdThenMove(a, b);
  // Heartbeats stop; state keeps coming.
  const MonoNs last_heartbeat = now;
  feed(a);
  int sent_after_timeout = 0;
  for (int i = 0; i < 40; ++i) {
    inputs.state_ns = now;
    const MonoNs t = now;
    const TickOutput out = tick();
    if (t - last_heartbeat >= 100 * kMs) {
      EXPECT_EQ(out.mode, StreamMode::kRobotDisabled);
      EXPECT_EQ(out.gate_reason, GateReason::kNoHeartbeat);
      sent_after_timeout += out.send_setpoints ? 1 : 0;
    } else {
      EXPECT_TRUE(out.send_setpoints);
    }
  }
  EXPECT_EQ(sent_after_timeout, 0);
  expectStopped(1, GateReason::kNoHeartbeat);
  // The mechanism sagged while disabled; on re-enable the streamer holds where it is now.
  expectEnabledHoldAt(JointVector{{0.9, 1.7}});
}

TEST_F(StreamerTest, BroadcastDisableStopsMotionAtTheNextTick) {
  const JointVector a{{0.2, 1.0}}, b{{1.6, 3.0}};
  holdThenMove(a, b);
  feed(a);
  inputs.broadcast_disable_ns = now;
  const TickOutput out = tick();
  EXPECT_FALSE(out.send_setpoints);
  EXPECT_EQ(out.mode, StreamMode::kRobotDisabled);
  EXPECT_EQ(out.gate_reason, GateReason::kBroadcastDisable);
  EXPECT_EQ(events.back().kind, StreamEventKind::kStopped);
  // Heartbeats that still claim "enabled" after the disable lift it; the hold is where it is.
  feed(JointVector{{0.25, 1.05}});
  const TickOutput again = tick();
  ASSERT_TRUE(again.send_setpoints);
  EXPECT_EQ(again.setpoints.position, (JointVector{{0.25, 1.05}}));
}

// The bug hil.daemon_faults caught: the disable and the next enabled heartbeat arrived 1-3 ms apart,
// both between two ticks, and the gate alone saw nothing but an enabled heartbeat after the disable.
TEST_F(StreamerTest, ADisableLiftedBeforeTheNextTickStillStopsMotionOnce) {
  const JointVector a{{0.2, 1.0}}, b{{1.6, 3.0}};
  holdThenMove(a, b);
  for (int i = 0; i < 3; ++i) tick();
  feed(a);
  inputs.broadcast_disable_ns = now - 3 * kMs;
  inputs.broadcast_disable_count = 1;
  inputs.heartbeat_ns = now - 1 * kMs;
  ASSERT_TRUE(evaluateGate(inputs, now, settings().gate).open());
  const TickOutput out = tick();
  EXPECT_FALSE(out.send_setpoints);
  EXPECT_EQ(out.gate_reason, GateReason::kBroadcastDisable);
  EXPECT_EQ(out.mode, StreamMode::kRobotDisabled);
  expectStopped(1, GateReason::kBroadcastDisable);
  // Latched once: the next tick, with the same count and the robot enabled, holds the measured position.
  expectEnabledHoldAt(JointVector{{0.3, 1.1}});
  // A second disable is a new event again.
  inputs.broadcast_disable_count = 2;
  EXPECT_FALSE(tick().send_setpoints);
  EXPECT_TRUE(tick().send_setpoints);
}

// ARM_CANCEL's release (docs/lcm.md, "Cancel and manual override"): nothing is streamed while the
// generation is odd; the status says RELEASED; the end of the release holds the measured position.
TEST_F(StreamerTest, ReleaseStreamsNothingUntilItEndsThenHoldsTheMeasuredPosition) {
  const JointVector a{{0.2, 1.0}}, b{{1.6, 3.0}};
  holdThenMove(a, b);
  feed(a);
  inputs.release_generation = 1;
  for (int i = 0; i < 10; ++i) {
    inputs.state_ns = now;
    inputs.heartbeat_ns = now;
    const TickOutput out = tick();
    EXPECT_FALSE(out.send_setpoints);
    EXPECT_EQ(out.mode, StreamMode::kReleased);
    EXPECT_EQ(out.gate_reason, GateReason::kReleased);
  }
  expectStopped(1, GateReason::kReleased);
  EXPECT_EQ(events.back().release_generation, 1u);
  inputs.release_generation = 2;
  EXPECT_FALSE(tick().send_setpoints);  // the new generation is latched as one stop
  expectEnabledHoldAt(JointVector{{0.7, 2.0}});
  EXPECT_EQ(events.back().release_generation, 2u);
}

TEST_F(StreamerTest, AReleaseEndedBeforeTheNextTickStillStopsOnce) {
  const JointVector a{{0.2, 1.0}}, b{{1.6, 3.0}};
  holdThenMove(a, b);
  feed(a);
  inputs.release_generation = 2;  // released and ended between two ticks
  const TickOutput out = tick();
  EXPECT_FALSE(out.send_setpoints);
  EXPECT_EQ(out.mode, StreamMode::kReleased);
  expectStopped(1, GateReason::kReleased);
  expectEnabledHoldAt(JointVector{{0.3, 1.1}});
}

TEST_F(StreamerTest, ProgramsOfAStoppedEpochAreRejected) {
  const JointVector a{{0.2, 1.0}}, b{{1.6, 3.0}};
  feed(a);
  tick();
  Program* p = moveFromRest(1, 1, a, b, 2.0);
  inputs.heartbeat_watchdog = false;  // disabled
  tick(p);
  EXPECT_EQ(events.back().kind, StreamEventKind::kRejected);
  EXPECT_EQ(events.back().reject_reason, RejectReason::kStaleBase);
}

TEST_F(StreamerTest, StopRequestHoldsTheCommandedPositionAndRefusesNewPrograms) {
  const JointVector a{{0.2, 1.0}}, b{{1.6, 3.0}};
  holdThenMove(a, b);
  TickOutput moving;
  for (int i = 0; i < 20; ++i) {
    feed(a);
    moving = tick();
  }
  ASSERT_EQ(moving.mode, StreamMode::kMoving);
  feed(a);
  const TickOutput held = tick(nullptr, true);
  EXPECT_EQ(held.mode, StreamMode::kHolding);
  EXPECT_EQ(held.setpoints.position, moving.setpoints.position);
  EXPECT_EQ(held.setpoints.velocity, JointVector::Zero(2));
  EXPECT_EQ(events.back().kind, StreamEventKind::kHolding);
  EXPECT_EQ(events.back().hold_cause, HoldCause::kShutdown);
  Program* p = moveFromRest(2, 2, moving.setpoints.position, a, 1.0);
  feed(a);
  tick(p, true);
  EXPECT_EQ(events.back().kind, StreamEventKind::kRejected);
}

TEST_F(StreamerTest, ASetpointThatCannotBeSentStopsStreamingThenTheMeasuredPositionIsHeld) {
  const JointVector a{{0.2, 1.0}};
  feed(a);
  tick();
  auto* p = new Program();
  std::vector<std::int64_t> dropped;
  ASSERT_TRUE(test::spliceInto(
      Program::holdAt(streamer.epoch(), a),
      {now, Segment{std::make_shared<test::NanAfterTrajectory>(0.02, (JointVector{{0.2, 1.0}})), 5, 0}, true, 1}, *p,
      dropped));
  int sent = 0, faulted = 0;
  TickOutput out;
  const MonoNs begin = now;
  while (now < begin + 900 * kMs) {  // the fault stops streaming for 1 s
    feed(JointVector{{0.21, 1.0}});
    out = tick(now == begin ? p : nullptr);
    if (out.send_setpoints) {
      ++sent;
      EXPECT_TRUE(std::isfinite(out.setpoints.position[0]));
    } else {
      EXPECT_EQ(out.mode, StreamMode::kFault);
      EXPECT_EQ(out.gate_reason, GateReason::kFault);
      ++faulted;
    }
  }
  EXPECT_EQ(sent, 5);  // t = 0 .. 20 ms of the program were finite
  EXPECT_GT(faulted, 150);
  bool fault = false, stopped = false;
  for (const auto& e : events) {
    fault |= e.kind == StreamEventKind::kFault && e.request_id == 5;
    stopped |= e.kind == StreamEventKind::kStopped && e.gate_reason == GateReason::kFault && e.request_id == 5;
  }
  EXPECT_TRUE(fault);
  EXPECT_TRUE(stopped);
  while (now < begin + 1100 * kMs) {
    feed(JointVector{{0.21, 1.0}});
    out = tick();
  }
  ASSERT_TRUE(out.send_setpoints);
  EXPECT_EQ(out.mode, StreamMode::kHolding);
  EXPECT_EQ(out.setpoints.position, (JointVector{{0.21, 1.0}}));
}

// A tick's event and retired lists are bounded; going past either is a defect, and it must stop
// the daemon rather than drop an answer the coordinator waits for or leak a program.
TEST(TickOutputDeathTest, PushingPastCapacityAborts) {
  TickOutput out;
  for (int i = 0; i < TickOutput::kMaxEvents; ++i) out.push(StreamEvent{});
  EXPECT_EQ(out.event_count, TickOutput::kMaxEvents);
  EXPECT_DEATH(out.push(StreamEvent{}), "");
}

TEST(TickOutputDeathTest, RetiringPastCapacityAborts) {
  TickOutput out;
  std::array<Program, TickOutput::kMaxRetired + 1> programs;
  out.retire(nullptr);  // nothing to retire: not counted
  for (int i = 0; i < TickOutput::kMaxRetired; ++i) out.retire(&programs[static_cast<size_t>(i)]);
  EXPECT_EQ(out.retired_count, TickOutput::kMaxRetired);
  EXPECT_DEATH(out.retire(&programs.back()), "");
}

}  // namespace
}  // namespace cyber::daemon

// The streamer and the frame writer together on a fake clock and a fake CAN port: what reaches
// the bus, period by period.

#include <gtest/gtest.h>

#include <vector>

#include "cyber/can/frame_kind.hpp"
#include "cyber/can/setpoint_codec.hpp"
#include "cyber/can/status_codec.hpp"
#include "cyber/daemon/frame_writer.hpp"
#include "cyber/daemon/streamer.hpp"
#include "fake_trajectory.hpp"
#include "reference_model.hpp"
#include "splice_into.hpp"

namespace cyber::daemon {
namespace {

constexpr MonoNs kMs = 1'000'000;
constexpr MonoNs kPeriod = 5 * kMs;

struct TimedFrame {
  MonoNs time;
  can::Frame frame;
};

struct ClockedCanPort final : CanPort {
  const MonoNs* clock = nullptr;
  std::vector<TimedFrame> frames;
  bool down = false;
  can::IoResult write(const can::Frame& frame) override {
    if (down) return can::ioResultFromErrno(ENETDOWN);
    frames.push_back({*clock, frame});
    return {};
  }
  [[nodiscard]] std::vector<TimedFrame> setpoints(std::uint8_t device) const {
    std::vector<TimedFrame> out;
    for (const auto& f : frames) {
      auto decoded = can::decodeSetpoint(f.frame);
      if (decoded && decoded.value().device == device) out.push_back(f);
    }
    return out;
  }
  [[nodiscard]] std::vector<can::Status> statuses() const {
    std::vector<can::Status> out;
    for (const auto& f : frames) {
      if (auto decoded = can::decodeStatus(f.frame)) out.push_back(decoded.value().status);
    }
    return out;
  }
};

class StreamToCan : public ::testing::Test {
 protected:
  StreamToCan() : streamer(HoldModel(robot), settings()), writer(port, FrameWriterSettings{{1, 2}, 3, 20}) {
    port.clock = &now;
  }
  static StreamerSettings settings() {
    StreamerSettings s;
    s.gate.require_robot_enabled = true;
    return s;
  }
  void tick(Program* offered = nullptr) {
    TickOutput out;
    streamer.tick(now, inputs, offered, false, out);
    for (int i = 0; i < out.retired_count; ++i) delete out.retired[static_cast<size_t>(i)];
    writer.write(out, 0);
    now += kPeriod;
  }
  void enabledFor(double seconds, const JointVector& measured) {
    const MonoNs end = now + secondsToNs(seconds);
    while (now < end) {
      inputs.state_ns = now;
      inputs.measured_q = measured;
      inputs.heartbeat_ns = now;
      inputs.heartbeat_watchdog = true;
      tick();
    }
  }

  const planner::RobotModel& robot = cyber::test::referenceModel();
  MonoNs now = 1000 * kMs;
  RobotInputs inputs;
  ClockedCanPort port;
  Streamer streamer;
  FrameWriter writer;
};

TEST_F(StreamToCan, EveryPeriodCarriesOneFramePerJointAndTheStatusComesAt10Hz) {
  enabledFor(1.0, JointVector{{0.2, 1.57}});
  const auto elevator = port.setpoints(1);
  const auto arm = port.setpoints(2);
  ASSERT_EQ(elevator.size(), 200u);
  ASSERT_EQ(arm.size(), 200u);
  for (size_t i = 1; i < elevator.size(); ++i) {
    EXPECT_EQ(elevator[i].time - elevator[i - 1].time, kPeriod);
    EXPECT_EQ(can::decodeSetpoint(elevator[i].frame).value().setpoint.sequence, static_cast<std::uint8_t>(i));
  }
  const auto statuses = port.statuses();
  ASSERT_EQ(statuses.size(), 10u);
  EXPECT_EQ(statuses.back().mode, can::Mode::kHolding);
  // Holding: zero velocity and gravity feedforward (arm at 1.57 rad: cos ~ 0).
  const auto hold = can::decodeSetpoint(arm.back().frame).value().setpoint;
  EXPECT_NEAR(hold.position, 1.57, 1e-5);
  EXPECT_EQ(hold.velocity, 0.0);
  EXPECT_NEAR(hold.feedforward_volts, robot.drive(1).kG_volts * std::cos(1.57), 1e-3);
  const auto elevator_hold = can::decodeSetpoint(elevator.back().frame).value().setpoint;
  EXPECT_NEAR(elevator_hold.feedforward_volts, robot.drive(0).kG_volts, 1e-3);
}

TEST_F(StreamToCan, AStaleHeartbeatStopsSetpointFramesWithinOnePeriodButNotTheStatus) {
  const JointVector a{{0.2, 1.57}};
  enabledFor(0.1, a);
  auto* program = new Program();
  std::vector<std::int64_t> dropped;
  ASSERT_TRUE(test::spliceInto(
      Program::holdAt(streamer.epoch(), a),
      {now, Segment{test::makeHermite(a, JointVector::Zero(2), (JointVector{{1.5, 3.0}}), 2.0, robot), 9, 0}, true, 1},
      *program, dropped));
  inputs.heartbeat_ns = now;
  inputs.state_ns = now;
  tick(program);
  const MonoNs last_heartbeat = inputs.heartbeat_ns;
  for (int i = 0; i < 60; ++i) {  // 300 ms with state but no heartbeat
    inputs.state_ns = now;
    tick();
  }
  MonoNs last_setpoint = 0;
  for (const auto& f : port.setpoints(1)) last_setpoint = std::max(last_setpoint, f.time);
  EXPECT_LT(last_setpoint, last_heartbeat + 100 * kMs);
  EXPECT_GE(last_setpoint, last_heartbeat + 100 * kMs - kPeriod);
  const auto statuses = port.statuses();
  ASSERT_FALSE(statuses.empty());
  EXPECT_EQ(statuses.back().mode, can::Mode::kRobotDisabled);
  EXPECT_EQ(statuses.back().request_id, 9);
  // The moving status carried the time remaining of the trajectory.
  bool moving_seen = false;
  for (const auto& s : statuses) moving_seen |= s.mode == can::Mode::kMoving && s.time_remaining_ms > 1500;
  EXPECT_TRUE(moving_seen);
}

TEST_F(StreamToCan, AnInterfaceThatGoesDownDropsFramesAndStreamingResumesWithFreshOnes) {
  const JointVector a{{0.2, 1.57}};
  enabledFor(0.1, a);
  port.down = true;
  enabledFor(0.2, a);
  EXPECT_EQ(writer.writeFailures(), 40 * 2 + 2);  // 40 periods x 2 setpoints + 2 status frames
  const size_t before = port.frames.size();
  port.down = false;
  const MonoNs back = now;
  enabledFor(0.05, JointVector{{0.3, 1.6}});
  // Nothing was queued: the first frames after the outage are from this period, not stale ones.
  ASSERT_GT(port.frames.size(), before);
  EXPECT_EQ(port.frames[before].time, back);
  EXPECT_EQ(port.setpoints(1).size(), 20u + 10u);
}

}  // namespace
}  // namespace cyber::daemon

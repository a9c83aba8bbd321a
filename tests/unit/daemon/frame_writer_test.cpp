#include "cyber/daemon/frame_writer.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <vector>

#include "cyber/can/frc_id.hpp"

namespace cyber::daemon {
namespace {

// Records every frame offered; fails while `failure` is set.
struct FakeCanPort final : CanPort {
  std::vector<can::Frame> offered;
  std::vector<can::Frame> accepted;
  std::optional<can::IoResult> failure;

  can::IoResult write(const can::Frame& frame) override {
    offered.push_back(frame);
    if (failure) return *failure;
    accepted.push_back(frame);
    return {};
  }
};

TickOutput moving(double q0, double q1) {
  TickOutput tick;
  tick.send_setpoints = true;
  tick.setpoints.position = JointVector{{q0, q1}};
  tick.setpoints.velocity = JointVector{{0.5, -1.25}};
  tick.setpoints.volts = JointVector{{2.5, -0.75}};
  tick.mode = StreamMode::kMoving;
  tick.gate_reason = GateReason::kOpen;
  tick.request_id = 0x123456;
  tick.remaining_s = 0.8501;
  return tick;
}

TEST(FrameWriter, WritesOneSetpointFramePerJointWithItsOwnSequence) {
  FakeCanPort port;
  FrameWriter writer(port, FrameWriterSettings{{1, 2}, 3, 20});
  for (int i = 0; i < 3; ++i) {
    const WriteReport report = writer.write(moving(1.23456, 2.5), 0);
    EXPECT_EQ(report.frames_written, 2);
    EXPECT_TRUE(report.wire.written);
    EXPECT_NEAR(report.wire.joints[0].position, 1.23456, 1e-9);
    EXPECT_EQ(report.wire.joints[1].sequence, i);
  }
  ASSERT_EQ(port.accepted.size(), 6u);
  auto first = can::decodeSetpoint(port.accepted[0]);
  auto second = can::decodeSetpoint(port.accepted[1]);
  ASSERT_TRUE(first && second);
  EXPECT_EQ(first.value().device, 1);
  EXPECT_EQ(second.value().device, 2);
  EXPECT_NEAR(second.value().setpoint.velocity, -1.25, 1e-9);
  EXPECT_NEAR(second.value().setpoint.feedforward_volts, -0.75, 1e-9);
  auto last = can::decodeSetpoint(port.accepted[4]);
  EXPECT_EQ(last.value().setpoint.sequence, 2);
  EXPECT_EQ(writer.framesSent(), 6);
}

TEST(FrameWriter, SendsTheStatusFrameEveryNTicksEvenWithoutSetpoints) {
  FakeCanPort port;
  FrameWriter writer(port, FrameWriterSettings{{1, 2}, 3, 4});
  TickOutput disabled;
  disabled.mode = StreamMode::kRobotDisabled;
  disabled.gate_reason = GateReason::kNoHeartbeat;
  disabled.request_id = -1;
  for (int i = 0; i < 8; ++i) {
    const WriteReport report = writer.write(disabled, can::fault::kPlanFailed);
    EXPECT_EQ(report.status_sent, i % 4 == 3) << i;
  }
  ASSERT_EQ(port.accepted.size(), 2u);
  auto status = can::decodeStatus(port.accepted[1]);
  ASSERT_TRUE(status);
  EXPECT_EQ(status.value().device, 3);
  EXPECT_EQ(status.value().status.mode, can::Mode::kRobotDisabled);
  EXPECT_EQ(status.value().status.request_id, 0xFFFF);
  EXPECT_EQ(status.value().status.fault_bits, can::fault::kPlanFailed);
  EXPECT_EQ(status.value().status.sequence, 1);
}

TEST(FrameWriter, StatusCarriesModeRequestRemainingTimeAndStaleState) {
  FakeCanPort port;
  FrameWriter writer(port, FrameWriterSettings{{1, 2}, 3, 1});
  TickOutput tick = moving(0.5, 1.0);
  tick.gate_reason = GateReason::kOpen;
  writer.write(tick, 0);
  auto status = can::decodeStatus(port.accepted.back());
  ASSERT_TRUE(status);
  EXPECT_EQ(status.value().status.mode, can::Mode::kMoving);
  EXPECT_EQ(status.value().status.request_id, 0x3456);
  EXPECT_EQ(status.value().status.time_remaining_ms, 851);
  TickOutput stale;
  stale.mode = StreamMode::kNoState;
  stale.gate_reason = GateReason::kStateStale;
  writer.write(stale, 0);
  EXPECT_EQ(can::decodeStatus(port.accepted.back()).value().status.fault_bits, can::fault::kStateStale);
}

TEST(FrameWriter, WriteFailuresDropFramesAndAreReportedOncePerBurst) {
  for (const int error : {ENOBUFS, ENETDOWN}) {
    FakeCanPort port;
    FrameWriter writer(port, FrameWriterSettings{{1, 2}, 3, 1000});
    writer.write(moving(0.5, 1.0), 0);
    port.failure = can::ioResultFromErrno(error);
    int started = 0;
    for (int i = 0; i < 50; ++i) {
      const WriteReport report = writer.write(moving(0.5 + 0.001 * i, 1.0), 0);
      EXPECT_EQ(report.frames_failed, 2);
      EXPECT_FALSE(report.wire.written);
      if (report.burst_started) {
        ++started;
        EXPECT_EQ(report.first_failure.error_number, error);
      }
    }
    EXPECT_EQ(started, 1);
    // Nothing is queued: each dropped frame was offered exactly once.
    EXPECT_EQ(port.offered.size(), 2u + 100u);
    port.failure.reset();
    const WriteReport recovered = writer.write(moving(0.7, 1.0), 0);
    EXPECT_TRUE(recovered.burst_ended);
    EXPECT_EQ(recovered.burst_failures, 100);
    EXPECT_TRUE(recovered.wire.written);
    // The frame after the outage carries the fresh setpoint, not an old one.
    EXPECT_NEAR(can::decodeSetpoint(port.accepted[2]).value().setpoint.position, 0.7, 1e-9);
    EXPECT_EQ(writer.writeFailures(), 100);
    EXPECT_EQ(writer.framesSent(), 4);
  }
}

TEST(FrameWriter, AFailingBusSetsTheWriteFailedFaultBit) {
  FakeCanPort port;
  FrameWriter writer(port, FrameWriterSettings{{1, 2}, 3, 1});
  port.failure = can::ioResultFromErrno(ENOBUFS);
  writer.write(moving(0.5, 1.0), 0);
  port.failure.reset();
  TickOutput idle;
  idle.mode = StreamMode::kHolding;
  idle.gate_reason = GateReason::kOpen;
  writer.write(idle, 0);  // the status frame itself succeeds and ends the burst
  EXPECT_EQ(can::decodeStatus(port.accepted.back()).value().status.fault_bits, can::fault::kCanWriteFailed);
}

}  // namespace
}  // namespace cyber::daemon

// The example frames of docs/can-protocol.md, checked byte for byte against the codec, and checked
// to appear in the document exactly as asserted here.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cyber/can/candump_log.hpp"
#include "cyber/can/frame_kind.hpp"
#include "cyber/can/robot_frames.hpp"
#include "cyber/can/setpoint_codec.hpp"
#include "cyber/can/status_codec.hpp"
#include "tool_run.hpp"

namespace cyber::can {
namespace {

// Reference device numbers ([daemon.devices] of config/reefscape-2025.toml).
constexpr std::uint8_t kElevatorDevice = 1;
constexpr std::uint8_t kArmDevice = 2;
constexpr std::uint8_t kDaemonDevice = 3;

constexpr const char* kElevatorLine = "(1700000000.000000) can0 0A080401#40E201F401B00407";
constexpr const char* kArmLine = "(1700000000.000050) can0 0A080402#B03CFF1EFB12FDFF";
constexpr const char* kHoldLine = "(1700000000.005000) can0 0A080402#B03CFF000012FD00";
constexpr const char* kStatusLine = "(1700000000.100000) can0 0A080803#02D204520300002A";
constexpr const char* kHeartbeatLine = "(1700000000.020000) can0 01011840#0000000012000000";
constexpr const char* kDisableLine = "(1700000000.040000) can0 00000000#";

std::string line(std::uint64_t s, std::uint32_t us, const Frame& frame) {
  return formatLogLine(LogRecord{LogTime{s, us}, "can0", frame});
}

TEST(ProtocolExamples, ElevatorSetpoint) {
  // 1.23456 m, 0.5 m/s, 1.2 V feedforward, sequence 7.
  const Frame frame = encodeSetpoint(kElevatorDevice, Setpoint{1.23456, 0.5, 1.2, 7}).value();
  EXPECT_EQ(line(1700000000, 0, frame), kElevatorLine);
}

TEST(ProtocolExamples, ArmSetpoint) {
  // -0.5 rad, -1.25 rad/s, -0.75 V feedforward, sequence 255 (the next one is 0).
  const Frame frame = encodeSetpoint(kArmDevice, Setpoint{-0.5, -1.25, -0.75, 255}).value();
  EXPECT_EQ(line(1700000000, 50, frame), kArmLine);
}

TEST(ProtocolExamples, ArmHoldSetpoint) {
  // Holding -0.5 rad: zero velocity, gravity feedforward -0.75 V, sequence wrapped to 0.
  const Frame frame = encodeSetpoint(kArmDevice, Setpoint{-0.5, 0.0, -0.75, 0}).value();
  EXPECT_EQ(line(1700000000, 5000, frame), kHoldLine);
}

TEST(ProtocolExamples, DaemonStatus) {
  // Moving, request 1234, 850 ms left, no faults, sequence 42.
  const Frame frame =
      encodeStatus(kDaemonDevice, Status{Mode::kMoving, requestIdLow16(1234), saturateTimeRemainingMs(0.85), 0, 42})
          .value();
  EXPECT_EQ(line(1700000000, 100000, frame), kStatusLine);
}

TEST(ProtocolExamples, Heartbeat) {
  // Blue alliance, enabled, teleoperated, system watchdog set: motion allowed.
  const Frame frame = encodeHeartbeat(Heartbeat{false, true, false, false, true});
  EXPECT_EQ(line(1700000000, 20000, frame), kHeartbeatLine);
}

TEST(ProtocolExamples, BroadcastDisable) { EXPECT_EQ(line(1700000000, 40000, makeBroadcastDisable()), kDisableLine); }

TEST(ProtocolExamples, ExamplesDecodeBack) {
  const auto elevator = decodeSetpoint(parseLogLine(kElevatorLine).value().frame);
  ASSERT_TRUE(elevator.ok());
  EXPECT_EQ(elevator.value().device, kElevatorDevice);
  EXPECT_EQ(elevator.value().setpoint, (Setpoint{1.23456, 0.5, 1.2, 7}));
  const auto arm = decodeSetpoint(parseLogLine(kArmLine).value().frame);
  ASSERT_TRUE(arm.ok());
  EXPECT_EQ(arm.value().setpoint, (Setpoint{-0.5, -1.25, -0.75, 255}));
  const auto status = decodeStatus(parseLogLine(kStatusLine).value().frame);
  ASSERT_TRUE(status.ok());
  EXPECT_EQ(status.value().status, (Status{Mode::kMoving, 1234, 850, 0, 42}));
  for (const HeartbeatLayout layout : {HeartbeatLayout::kRoboRio, HeartbeatLayout::kSystemcore}) {
    const auto heartbeat = decodeHeartbeat(parseLogLine(kHeartbeatLine).value().frame, layout);
    ASSERT_TRUE(heartbeat.ok());
    EXPECT_TRUE(heartbeat.value().enabled);
    EXPECT_TRUE(heartbeat.value().system_watchdog);
    EXPECT_FALSE(heartbeat.value().ftc_motor_override);
  }
  EXPECT_EQ(classify(parseLogLine(kDisableLine).value().frame), FrameKind::kBroadcastDisable);
}

TEST(ProtocolExamples, DocumentShowsExactlyTheseFrames) {
  const std::string doc = test::readFile(std::string(CYBER_SOURCE_DIR) + "/docs/can-protocol.md");
  ASSERT_FALSE(doc.empty()) << "docs/can-protocol.md is missing or empty";
  for (const char* example : {kElevatorLine, kArmLine, kHoldLine, kStatusLine, kHeartbeatLine, kDisableLine}) {
    EXPECT_NE(doc.find(example), std::string::npos) << "not in docs/can-protocol.md: " << example;
  }
  // The ids worked out in the document.
  for (const char* id : {"0x0A080401", "0x0A080402", "0x0A080803", "0x01011840"}) {
    EXPECT_NE(doc.find(id), std::string::npos) << id;
  }
}

}  // namespace
}  // namespace cyber::can

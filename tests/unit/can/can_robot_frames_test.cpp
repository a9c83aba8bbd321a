#include <gtest/gtest.h>

#include <linux/can/error.h>

#include "cyber/can/bus_error.hpp"
#include "cyber/can/frame_kind.hpp"
#include "cyber/can/frc_id.hpp"
#include "cyber/can/robot_frames.hpp"
#include "cyber/can/setpoint_codec.hpp"
#include "cyber/can/status_codec.hpp"

namespace cyber::can {
namespace {

Frame heartbeatWith(std::uint8_t flags, std::uint8_t byte5 = 0x00) {
  Frame frame;
  frame.id = 0x01011840u;
  frame.extended = true;
  frame.dlc = 8;
  frame.data = {0x11, 0x22, 0x33, 0x44, flags, byte5, 0x77, 0x88};  // the other bytes are ignored
  return frame;
}

constexpr HeartbeatLayout kBothLayouts[] = {HeartbeatLayout::kRoboRio, HeartbeatLayout::kSystemcore};

Heartbeat flags(bool red, bool enabled, bool autonomous, bool test, bool watchdog) {
  return Heartbeat{red, enabled, autonomous, test, watchdog};
}

// docs/can-protocol.md, "Robot heartbeat": the flags sit in byte 4 from its least significant bit
// (the 64-bit word is sent most significant byte first), the tournament type above them.
TEST(Heartbeat, FlagsFromTheLeastSignificantBitOfByte4InBothLayouts) {
  for (const HeartbeatLayout layout : kBothLayouts) {
    EXPECT_EQ(decodeHeartbeat(heartbeatWith(0x01), layout).value(), flags(true, false, false, false, false));
    EXPECT_EQ(decodeHeartbeat(heartbeatWith(0x02), layout).value(), flags(false, true, false, false, false));
    EXPECT_EQ(decodeHeartbeat(heartbeatWith(0x04), layout).value(), flags(false, false, true, false, false));
    EXPECT_EQ(decodeHeartbeat(heartbeatWith(0x08), layout).value(), flags(false, false, false, true, false));
    EXPECT_EQ(decodeHeartbeat(heartbeatWith(0x10), layout).value(), flags(false, false, false, false, true));
    EXPECT_EQ(decodeHeartbeat(heartbeatWith(0xE0), layout).value(), Heartbeat{});  // tournament type
    EXPECT_EQ(decodeHeartbeat(heartbeatWith(0x1F), layout).value(), flags(true, true, true, true, true));
  }
}

// A roboRIO enabled with the system watchdog sends byte 4 = 0x13 on the red alliance
// (tests/vectors/heartbeat_frames.txt); read from the most significant bit that would be test mode
// without the watchdog, and 0x48 would be "enabled + watchdog" when it is test mode.
TEST(Heartbeat, ARealEnabledFrameHasTheWatchdogBitAnd0x48DoesNot) {
  for (const HeartbeatLayout layout : kBothLayouts) {
    const Heartbeat enabled = decodeHeartbeat(heartbeatWith(0x13), layout).value();
    EXPECT_TRUE(enabled.system_watchdog);
    EXPECT_TRUE(enabled.enabled);
    EXPECT_FALSE(enabled.test);
    const Heartbeat test_mode = decodeHeartbeat(heartbeatWith(0x48), layout).value();
    EXPECT_FALSE(test_mode.system_watchdog);
    EXPECT_FALSE(test_mode.enabled);
    EXPECT_TRUE(test_mode.test);
  }
}

// The bit added for 2027: byte 5's top bit is Systemcore's FTC motor override, and the top bit of
// the roboRIO's 6-bit replay number.
TEST(Heartbeat, Byte5TopBitIsTheOverrideOnSystemcoreAndAReplayBitOnTheRoboRio) {
  const Frame frame = heartbeatWith(0x12, 0x80);
  const Heartbeat systemcore = decodeHeartbeat(frame, HeartbeatLayout::kSystemcore).value();
  EXPECT_TRUE(systemcore.ftc_motor_override);
  EXPECT_EQ(systemcore.replay_number, 0);
  EXPECT_TRUE(systemcore.system_watchdog);
  const Heartbeat roborio = decodeHeartbeat(frame, HeartbeatLayout::kRoboRio).value();
  EXPECT_FALSE(roborio.ftc_motor_override);
  EXPECT_EQ(roborio.replay_number, 32);
  // The replay number starts at bit 2 of byte 5; bits 0 and 1 belong to the match number.
  EXPECT_EQ(decodeHeartbeat(heartbeatWith(0x00, 0xFF), HeartbeatLayout::kRoboRio).value().replay_number, 63);
  EXPECT_EQ(decodeHeartbeat(heartbeatWith(0x00, 0xFF), HeartbeatLayout::kSystemcore).value().replay_number, 31);
  EXPECT_EQ(decodeHeartbeat(heartbeatWith(0x00, 0x03), HeartbeatLayout::kSystemcore).value(), Heartbeat{});
}

TEST(Heartbeat, EveryRepresentableHeartbeatRoundTripsInItsLayout) {
  for (const HeartbeatLayout layout : kBothLayouts) {
    const int replays = layout == HeartbeatLayout::kRoboRio ? 64 : 32;
    const int overrides = layout == HeartbeatLayout::kRoboRio ? 1 : 2;
    for (int bits = 0; bits < 32; ++bits) {
      for (int replay = 0; replay < replays; ++replay) {
        for (int override_flag = 0; override_flag < overrides; ++override_flag) {
          Heartbeat in = flags((bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0, (bits & 8) != 0, (bits & 16) != 0);
          in.replay_number = static_cast<std::uint8_t>(replay);
          in.ftc_motor_override = override_flag != 0;
          const Frame frame = encodeHeartbeat(in, layout);
          ASSERT_EQ(frame.id, kHeartbeatId);
          ASSERT_TRUE(frame.extended);
          ASSERT_EQ(frame.dlc, 8);
          ASSERT_TRUE(isWellFormed(frame));
          ASSERT_EQ(decodeHeartbeat(frame, layout).value(), in);
        }
      }
    }
  }
}

TEST(Heartbeat, EncodingCutsFieldsToTheLayout) {
  Heartbeat h;
  h.ftc_motor_override = true;
  h.replay_number = 63;
  EXPECT_EQ(encodeHeartbeat(h, HeartbeatLayout::kRoboRio).data[5], 0xFC);     // no override bit
  EXPECT_EQ(encodeHeartbeat(h, HeartbeatLayout::kSystemcore).data[5], 0xFC);  // 31 and the override
  h.ftc_motor_override = false;
  EXPECT_EQ(encodeHeartbeat(h, HeartbeatLayout::kSystemcore).data[5], 0x7C);
  EXPECT_EQ(encodeHeartbeat(Heartbeat{}), encodeHeartbeat(Heartbeat{}, HeartbeatLayout::kRoboRio));
}

TEST(Heartbeat, RejectsWrongLengthIdAndFlags) {
  for (const HeartbeatLayout layout : kBothLayouts) {
    for (std::uint8_t dlc = 0; dlc < 8; ++dlc) {
      Frame frame = heartbeatWith(0x12);
      frame.dlc = dlc;
      EXPECT_EQ(decodeHeartbeat(frame, layout).status(), CodecError::kWrongLength) << int{dlc};
    }
    Frame wrong_id = heartbeatWith(0x12);
    wrong_id.id = 0x01011841u;
    EXPECT_EQ(decodeHeartbeat(wrong_id, layout).status(), CodecError::kWrongId);
    Frame standard = heartbeatWith(0x12);
    standard.extended = false;
    standard.id = 0x040;
    EXPECT_EQ(decodeHeartbeat(standard, layout).status(), CodecError::kNotExtended);
    Frame remote = heartbeatWith(0x12);
    remote.remote = true;
    EXPECT_EQ(decodeHeartbeat(remote, layout).status(), CodecError::kRemoteFrame);
  }
}

TEST(BroadcastDisable, IdZeroInEitherFormat) {
  const Frame disable = makeBroadcastDisable();
  EXPECT_EQ(disable.id, 0u);
  EXPECT_TRUE(disable.extended);
  EXPECT_EQ(disable.dlc, 0);
  EXPECT_TRUE(isBroadcastDisable(disable));
  Frame standard;
  standard.dlc = 8;
  EXPECT_TRUE(isBroadcastDisable(standard));
  Frame not_zero = disable;
  not_zero.id = 1;
  EXPECT_FALSE(isBroadcastDisable(not_zero));
  Frame error = disable;
  error.error = true;
  error.extended = false;
  EXPECT_FALSE(isBroadcastDisable(error));
}

TEST(Classify, EachKind) {
  EXPECT_EQ(classify(encodeSetpoint(1, Setpoint{}).value()), FrameKind::kSetpoint);
  EXPECT_EQ(classify(encodeSetpoint(63, Setpoint{}).value()), FrameKind::kSetpoint);
  EXPECT_EQ(classify(encodeStatus(3, Status{}).value()), FrameKind::kStatus);
  EXPECT_EQ(classify(encodeHeartbeat(Heartbeat{})), FrameKind::kHeartbeat);
  EXPECT_EQ(classify(makeBroadcastDisable()), FrameKind::kBroadcastDisable);
  Frame error;
  error.error = true;
  error.id = CAN_ERR_BUSOFF;
  EXPECT_EQ(classify(error), FrameKind::kBusError);
  Frame other;
  other.extended = true;
  other.id = packFrcId(FrcId{2, 4, 1, 0, 1});  // a CTRE motor controller, not us
  EXPECT_EQ(classify(other), FrameKind::kOther);
  other.id = packFrcId(FrcId{10, 8, 3, 0, 1});  // our type, unknown API
  EXPECT_EQ(classify(other), FrameKind::kOther);
  Frame standard;
  standard.id = 0x401;  // same low bits as a setpoint, but 11-bit
  EXPECT_EQ(classify(standard), FrameKind::kOther);
  // A setpoint id with a bad payload is still a setpoint: its decoder reports the error.
  Frame short_setpoint = encodeSetpoint(1, Setpoint{}).value();
  short_setpoint.dlc = 7;
  EXPECT_EQ(classify(short_setpoint), FrameKind::kSetpoint);
  for (auto kind : {FrameKind::kSetpoint, FrameKind::kStatus, FrameKind::kHeartbeat, FrameKind::kBroadcastDisable,
                    FrameKind::kBusError, FrameKind::kOther}) {
    EXPECT_FALSE(toString(kind).empty());
  }
}

TEST(BusError, DecodesErrorClasses) {
  Frame frame;
  frame.error = true;
  frame.dlc = 8;
  frame.id = CAN_ERR_BUSOFF;
  EXPECT_EQ(decodeBusError(frame).value(), (BusError{true, false, 0, false, false, false}));
  frame.id = CAN_ERR_CRTL;
  frame.data[1] = CAN_ERR_CRTL_TX_PASSIVE;
  EXPECT_EQ(decodeBusError(frame).value(), (BusError{false, true, CAN_ERR_CRTL_TX_PASSIVE, false, false, false}));
  frame.id = CAN_ERR_TX_TIMEOUT | CAN_ERR_RESTARTED;
  frame.data[1] = 0;
  EXPECT_EQ(decodeBusError(frame).value(), (BusError{false, false, 0, true, true, false}));
  frame.id = CAN_ERR_ACK;
  EXPECT_EQ(decodeBusError(frame).value(), (BusError{false, false, 0, false, false, true}));
  Frame data = encodeHeartbeat(Heartbeat{});
  EXPECT_EQ(decodeBusError(data).status(), CodecError::kWrongId);
}

}  // namespace
}  // namespace cyber::can

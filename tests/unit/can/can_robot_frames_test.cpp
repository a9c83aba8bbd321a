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

Frame heartbeatWithFlags(std::uint8_t flags) {
  Frame frame;
  frame.id = 0x01011840u;
  frame.extended = true;
  frame.dlc = 8;
  frame.data = {0x11, 0x22, 0x33, 0x44, flags, 0x66, 0x77, 0x88};  // other bytes are ignored
  return frame;
}

TEST(Heartbeat, EachBitFromTheMostSignificant) {
  EXPECT_EQ(decodeHeartbeat(heartbeatWithFlags(0x80)).value(), (Heartbeat{true, false, false, false, false}));
  EXPECT_EQ(decodeHeartbeat(heartbeatWithFlags(0x40)).value(), (Heartbeat{false, true, false, false, false}));
  EXPECT_EQ(decodeHeartbeat(heartbeatWithFlags(0x20)).value(), (Heartbeat{false, false, true, false, false}));
  EXPECT_EQ(decodeHeartbeat(heartbeatWithFlags(0x10)).value(), (Heartbeat{false, false, false, true, false}));
  EXPECT_EQ(decodeHeartbeat(heartbeatWithFlags(0x08)).value(), (Heartbeat{false, false, false, false, true}));
  EXPECT_EQ(decodeHeartbeat(heartbeatWithFlags(0x07)).value(), Heartbeat{});  // low bits unused
  EXPECT_EQ(decodeHeartbeat(heartbeatWithFlags(0xF8)).value(), (Heartbeat{true, true, true, true, true}));
}

TEST(Heartbeat, AllFlagCombinationsRoundTrip) {
  for (int bits = 0; bits < 32; ++bits) {
    const Heartbeat in{(bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0, (bits & 8) != 0, (bits & 16) != 0};
    const Frame frame = encodeHeartbeat(in);
    EXPECT_EQ(frame.id, kHeartbeatId);
    EXPECT_TRUE(frame.extended);
    EXPECT_EQ(frame.dlc, 8);
    EXPECT_TRUE(isWellFormed(frame));
    EXPECT_EQ(decodeHeartbeat(frame).value(), in);
  }
}

TEST(Heartbeat, RejectsWrongLengthIdAndFlags) {
  for (std::uint8_t dlc = 0; dlc < 8; ++dlc) {
    Frame frame = heartbeatWithFlags(0x48);
    frame.dlc = dlc;
    EXPECT_EQ(decodeHeartbeat(frame).error(), CodecError::kWrongLength) << int{dlc};
  }
  Frame wrong_id = heartbeatWithFlags(0x48);
  wrong_id.id = 0x01011841u;
  EXPECT_EQ(decodeHeartbeat(wrong_id).error(), CodecError::kWrongId);
  Frame standard = heartbeatWithFlags(0x48);
  standard.extended = false;
  standard.id = 0x040;
  EXPECT_EQ(decodeHeartbeat(standard).error(), CodecError::kNotExtended);
  Frame remote = heartbeatWithFlags(0x48);
  remote.remote = true;
  EXPECT_EQ(decodeHeartbeat(remote).error(), CodecError::kRemoteFrame);
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
  EXPECT_EQ(decodeBusError(data).error(), CodecError::kWrongId);
}

}  // namespace
}  // namespace cyber::can

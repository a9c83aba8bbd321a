#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "cyber/can/frc_id.hpp"
#include "cyber/can/status_codec.hpp"

namespace cyber::can {
namespace {

TEST(StatusCodec, HandComputedBytes) {
  // request 1234 = 0x04D2, 850 ms = 0x0352, sequence 42 = 0x2A.
  const auto frame = encodeStatus(3, Status{Mode::kMoving, 1234, 850, fault::kStreamOverrun, 42});
  ASSERT_TRUE(frame.ok());
  EXPECT_EQ(frame.value().id, 0x0A080803u);
  EXPECT_TRUE(frame.value().extended);
  EXPECT_EQ(frame.value().dlc, 8);
  EXPECT_EQ(frame.value().data, (std::array<std::uint8_t, 8>{0x02, 0xD2, 0x04, 0x52, 0x03, 0x04, 0x00, 0x2A}));
}

TEST(StatusCodec, ModeNumbersAreTheContract) {
  EXPECT_EQ(static_cast<int>(Mode::kNoState), 0);
  EXPECT_EQ(static_cast<int>(Mode::kHolding), 1);
  EXPECT_EQ(static_cast<int>(Mode::kMoving), 2);
  EXPECT_EQ(static_cast<int>(Mode::kFault), 3);
  EXPECT_EQ(static_cast<int>(Mode::kRobotDisabled), 4);
  EXPECT_EQ(static_cast<int>(Mode::kReleased), 5);
  EXPECT_EQ(toString(Mode::kMoving), "moving");
  EXPECT_EQ(toString(Mode::kRobotDisabled), "robot-disabled");
  EXPECT_EQ(toString(Mode::kReleased), "released");
  EXPECT_EQ(toString(static_cast<Mode>(9)), "undefined");
}

TEST(StatusCodec, RandomStatusesRoundTrip) {
  std::mt19937 rng(31337);
  std::uniform_int_distribution<int> mode(0, 5), u16(0, 65535), u8(0, 255), device(0, 63);
  for (int i = 0; i < 20000; ++i) {
    const Status in{static_cast<Mode>(mode(rng)), static_cast<std::uint16_t>(u16(rng)),
                    static_cast<std::uint16_t>(u16(rng)), static_cast<std::uint8_t>(u8(rng)),
                    static_cast<std::uint8_t>(u8(rng))};
    const auto dev = static_cast<std::uint8_t>(device(rng));
    const auto frame = encodeStatus(dev, in);
    ASSERT_TRUE(frame.ok());
    ASSERT_EQ(frame.value().data[6], 0);
    const auto out = decodeStatus(frame.value());
    ASSERT_TRUE(out.ok());
    ASSERT_EQ(out.value().device, dev);
    ASSERT_EQ(out.value().status, in);
  }
}

// ARM_CANCEL's release (docs/can-protocol.md): mode 5 on the wire, byte 0 = 0x05.
TEST(StatusCodec, ReleasedModeRoundTrips) {
  const Status in{Mode::kReleased, requestIdLow16(-1), 0, 0, 9};
  const auto frame = encodeStatus(3, in);
  ASSERT_TRUE(frame.ok());
  EXPECT_EQ(frame.value().data[0], 0x05);
  const auto out = decodeStatus(frame.value());
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(out.value().status, in);
}

TEST(StatusCodec, SaturatesTimeRemaining) {
  EXPECT_EQ(saturateTimeRemainingMs(0.0), 0);
  EXPECT_EQ(saturateTimeRemainingMs(-1.0), 0);
  EXPECT_EQ(saturateTimeRemainingMs(std::numeric_limits<double>::quiet_NaN()), 0);
  EXPECT_EQ(saturateTimeRemainingMs(0.0001), 1);  // rounds up: 0 only when nothing is left
  EXPECT_EQ(saturateTimeRemainingMs(0.85), 850);
  EXPECT_EQ(saturateTimeRemainingMs(65.534), 65534);
  EXPECT_EQ(saturateTimeRemainingMs(65.535), 65535);
  EXPECT_EQ(saturateTimeRemainingMs(65.536), 65535);
  EXPECT_EQ(saturateTimeRemainingMs(1e9), 65535);
  EXPECT_EQ(saturateTimeRemainingMs(std::numeric_limits<double>::infinity()), 65535);
}

TEST(StatusCodec, RequestIdKeepsLow16Bits) {
  EXPECT_EQ(requestIdLow16(0), 0);
  EXPECT_EQ(requestIdLow16(1234), 1234);
  EXPECT_EQ(requestIdLow16(0x12345678), 0x5678);
  EXPECT_EQ(requestIdLow16(65536), 0);
  EXPECT_EQ(requestIdLow16(-1), 0xFFFF);
}

TEST(StatusCodec, SequenceWraps) {
  std::uint8_t sequence = 254;
  for (int i = 0; i < 4; ++i) {
    const auto frame = encodeStatus(3, Status{Mode::kHolding, 0, 0, 0, sequence});
    ASSERT_TRUE(frame.ok());
    EXPECT_EQ(decodeStatus(frame.value()).value().status.sequence, sequence);
    ++sequence;
  }
  EXPECT_EQ(sequence, 2);
}

TEST(StatusCodec, EncodeRejectsBadDeviceAndMode) {
  EXPECT_EQ(encodeStatus(64, Status{}).status(), CodecError::kDeviceOutOfRange);
  EXPECT_EQ(encodeStatus(1, Status{static_cast<Mode>(6), 0, 0, 0, 0}).status(), CodecError::kBadMode);
}

TEST(StatusCodec, DecodeRejectsWrongFrames) {
  const Frame good = encodeStatus(3, Status{Mode::kFault, 7, 0, fault::kBusError, 1}).value();
  for (std::uint8_t mode = 6; mode != 0; ++mode) {
    Frame frame = good;
    frame.data[0] = mode;
    ASSERT_EQ(decodeStatus(frame).status(), CodecError::kBadMode) << int{mode};
  }
  for (std::uint8_t dlc = 0; dlc < 8; ++dlc) {
    Frame frame = good;
    frame.dlc = dlc;
    ASSERT_EQ(decodeStatus(frame).status(), CodecError::kWrongLength);
  }
  Frame setpoint_id = good;
  setpoint_id.id = teamFrameId(kSetpointApiClass, kSetpointApiIndex, 3);
  EXPECT_EQ(decodeStatus(setpoint_id).status(), CodecError::kWrongId);
  Frame standard = good;
  standard.extended = false;
  standard.id = 0x003;
  EXPECT_EQ(decodeStatus(standard).status(), CodecError::kNotExtended);
  Frame remote = good;
  remote.remote = true;
  EXPECT_EQ(decodeStatus(remote).status(), CodecError::kRemoteFrame);
}

}  // namespace
}  // namespace cyber::can

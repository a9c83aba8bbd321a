#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "cyber/can/frc_id.hpp"
#include "cyber/can/setpoint_codec.hpp"

namespace cyber::can {
namespace {

Frame mustEncode(std::uint8_t device, const Setpoint& setpoint) {
  const auto frame = encodeSetpoint(device, setpoint);
  EXPECT_TRUE(frame.ok()) << toString(frame.status());
  return frame.ok() ? frame.value() : Frame{};
}

CodecError encodeError(const Setpoint& setpoint, std::uint8_t device = 1) {
  const auto frame = encodeSetpoint(device, setpoint);
  EXPECT_FALSE(frame.ok());
  return frame.status();
}

TEST(SetpointCodec, HandComputedBytes) {
  // 1.23456 m = 123456 = 0x01E240; 0.5 m/s = 500 = 0x01F4; 1.2 V = 1200 mV = 0x04B0.
  const Frame frame = mustEncode(1, Setpoint{1.23456, 0.5, 1.2, 7});
  EXPECT_TRUE(frame.extended);
  EXPECT_FALSE(frame.remote);
  EXPECT_EQ(frame.id, 0x0A080401u);
  EXPECT_EQ(frame.dlc, 8);
  EXPECT_EQ(frame.data, (std::array<std::uint8_t, 8>{0x40, 0xE2, 0x01, 0xF4, 0x01, 0xB0, 0x04, 0x07}));
}

TEST(SetpointCodec, HandComputedNegativeBytes) {
  // -50000 = 0xFF3CB0 (24-bit); -1250 = 0xFB1E; -750 = 0xFD12.
  const Frame frame = mustEncode(2, Setpoint{-0.5, -1.25, -0.75, 255});
  EXPECT_EQ(frame.id, 0x0A080402u);
  EXPECT_EQ(frame.data, (std::array<std::uint8_t, 8>{0xB0, 0x3C, 0xFF, 0x1E, 0xFB, 0x12, 0xFD, 0xFF}));
}

TEST(SetpointCodec, DecodesHandComputedBytes) {
  Frame frame;
  frame.id = 0x0A080405u;
  frame.extended = true;
  frame.dlc = 8;
  frame.data = {0x01, 0x00, 0x80, 0xFF, 0x7F, 0x00, 0x80, 0x2A};
  // 0x800001 = -8388607 counts; 0x7FFF = 32767; 0x8000 = -32768.
  const auto decoded = decodeSetpoint(frame);
  ASSERT_TRUE(decoded.ok());
  EXPECT_EQ(decoded.value().device, 5);
  EXPECT_EQ(decoded.value().setpoint.position, -83.88607);
  EXPECT_EQ(decoded.value().setpoint.velocity, 32.767);
  EXPECT_EQ(decoded.value().setpoint.feedforward_volts, -32.768);
  EXPECT_EQ(decoded.value().setpoint.sequence, 42);
}

TEST(SetpointCodec, PositionLimits) {
  EXPECT_TRUE(encodeSetpoint(1, Setpoint{83.88607, 0, 0, 0}).ok());
  EXPECT_EQ(encodeError(Setpoint{83.88608, 0, 0, 0}), CodecError::kPositionOutOfRange);
  EXPECT_TRUE(encodeSetpoint(1, Setpoint{-83.88608, 0, 0, 0}).ok());
  EXPECT_EQ(encodeError(Setpoint{-83.88609, 0, 0, 0}), CodecError::kPositionOutOfRange);
  // Rounding to nearest: just below the half count still fits, the half count rounds away.
  EXPECT_TRUE(encodeSetpoint(1, Setpoint{83.886074, 0, 0, 0}).ok());
  EXPECT_EQ(encodeError(Setpoint{83.886075, 0, 0, 0}), CodecError::kPositionOutOfRange);
  EXPECT_EQ(encodeError(Setpoint{1e300, 0, 0, 0}), CodecError::kPositionOutOfRange);

  const Frame top = mustEncode(1, Setpoint{83.88607, 0, 0, 0});
  EXPECT_EQ(top.data[0], 0xFF);
  EXPECT_EQ(top.data[1], 0xFF);
  EXPECT_EQ(top.data[2], 0x7F);
  const Frame bottom = mustEncode(1, Setpoint{-83.88608, 0, 0, 0});
  EXPECT_EQ(bottom.data[0], 0x00);
  EXPECT_EQ(bottom.data[1], 0x00);
  EXPECT_EQ(bottom.data[2], 0x80);
  EXPECT_EQ(decodeSetpoint(bottom).value().setpoint.position, -83.88608);
}

TEST(SetpointCodec, VelocityAndVoltageLimits) {
  EXPECT_TRUE(encodeSetpoint(1, Setpoint{0, 32.767, 0, 0}).ok());
  EXPECT_EQ(encodeError(Setpoint{0, 32.768, 0, 0}), CodecError::kVelocityOutOfRange);
  EXPECT_TRUE(encodeSetpoint(1, Setpoint{0, -32.768, 0, 0}).ok());
  EXPECT_EQ(encodeError(Setpoint{0, -32.769, 0, 0}), CodecError::kVelocityOutOfRange);
  EXPECT_TRUE(encodeSetpoint(1, Setpoint{0, 0, 32.767, 0}).ok());
  EXPECT_EQ(encodeError(Setpoint{0, 0, 32.768, 0}), CodecError::kVoltageOutOfRange);
  EXPECT_TRUE(encodeSetpoint(1, Setpoint{0, 0, -32.768, 0}).ok());
  EXPECT_EQ(encodeError(Setpoint{0, 0, -32.769, 0}), CodecError::kVoltageOutOfRange);
}

// The magnitudes the streamer checks setpoints against (SetpointLimits) encode with both signs.
TEST(SetpointCodec, TheMaxMagnitudesEncodeWithEitherSign) {
  for (const double sign : {1.0, -1.0}) {
    EXPECT_TRUE(encodeSetpoint(1, Setpoint{sign * kMaxPositionMagnitude, sign * kMaxVelocityMagnitude,
                                           sign * kMaxVoltageMagnitude, 0})
                    .ok());
  }
  EXPECT_EQ(encodeError(Setpoint{kMaxPositionMagnitude + 1e-5, 0, 0, 0}), CodecError::kPositionOutOfRange);
  EXPECT_EQ(encodeError(Setpoint{0, kMaxVelocityMagnitude + 1e-3, 0, 0}), CodecError::kVelocityOutOfRange);
  EXPECT_EQ(encodeError(Setpoint{0, 0, kMaxVoltageMagnitude + 1e-3, 0}), CodecError::kVoltageOutOfRange);
}

TEST(SetpointCodec, NonFiniteValuesAreErrors) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(encodeError(Setpoint{nan, 0, 0, 0}), CodecError::kPositionOutOfRange);
  EXPECT_EQ(encodeError(Setpoint{-inf, 0, 0, 0}), CodecError::kPositionOutOfRange);
  EXPECT_EQ(encodeError(Setpoint{0, nan, 0, 0}), CodecError::kVelocityOutOfRange);
  EXPECT_EQ(encodeError(Setpoint{0, inf, 0, 0}), CodecError::kVelocityOutOfRange);
  EXPECT_EQ(encodeError(Setpoint{0, 0, nan, 0}), CodecError::kVoltageOutOfRange);
  EXPECT_EQ(encodeError(Setpoint{0, 0, -inf, 0}), CodecError::kVoltageOutOfRange);
}

TEST(SetpointCodec, DeviceNumberRange) {
  EXPECT_EQ(mustEncode(63, Setpoint{}).id, 0x0A08043Fu);
  EXPECT_EQ(encodeError(Setpoint{}, 64), CodecError::kDeviceOutOfRange);
  EXPECT_EQ(encodeError(Setpoint{}, 255), CodecError::kDeviceOutOfRange);
}

TEST(SetpointCodec, RoundsToNearestCount) {
  EXPECT_EQ(decodeSetpoint(mustEncode(1, Setpoint{0.000014, 0.0014, 0.0014, 0})).value().setpoint,
            (Setpoint{0.00001, 0.001, 0.001, 0}));
  EXPECT_EQ(decodeSetpoint(mustEncode(1, Setpoint{0.000016, 0.0016, 0.0016, 0})).value().setpoint,
            (Setpoint{0.00002, 0.002, 0.002, 0}));
  EXPECT_EQ(decodeSetpoint(mustEncode(1, Setpoint{-0.000016, -0.0016, -0.0016, 0})).value().setpoint,
            (Setpoint{-0.00002, -0.002, -0.002, 0}));
}

TEST(SetpointCodec, SequenceWrapsThroughAllValues) {
  std::uint8_t sequence = 250;
  for (int i = 0; i < 12; ++i) {
    const Frame frame = mustEncode(2, Setpoint{0.1, 0, 0, sequence});
    EXPECT_EQ(frame.data[7], sequence);
    EXPECT_EQ(decodeSetpoint(frame).value().setpoint.sequence, sequence);
    ++sequence;  // 255 -> 0
  }
  EXPECT_EQ(sequence, 6);
}

TEST(SetpointCodec, RandomValuesRoundTripWithinHalfACount) {
  std::mt19937_64 rng(424242);
  std::uniform_real_distribution<double> position(-83.886, 83.886), velocity(-32.76, 32.76), volts(-32.76, 32.76);
  std::uniform_int_distribution<int> device(0, 63), sequence(0, 255);
  for (int i = 0; i < 20000; ++i) {
    const Setpoint in{position(rng), velocity(rng), volts(rng), static_cast<std::uint8_t>(sequence(rng))};
    const auto dev = static_cast<std::uint8_t>(device(rng));
    const auto frame = encodeSetpoint(dev, in);
    ASSERT_TRUE(frame.ok()) << i;
    const auto out = decodeSetpoint(frame.value());
    ASSERT_TRUE(out.ok()) << i;
    ASSERT_EQ(out.value().device, dev);
    ASSERT_LE(std::fabs(out.value().setpoint.position - in.position), 0.5e-5 + 1e-12) << i;
    ASSERT_LE(std::fabs(out.value().setpoint.velocity - in.velocity), 0.5e-3 + 1e-12) << i;
    ASSERT_LE(std::fabs(out.value().setpoint.feedforward_volts - in.feedforward_volts), 0.5e-3 + 1e-12) << i;
    ASSERT_EQ(out.value().setpoint.sequence, in.sequence);
    // The decoded values are exactly representable on the wire: re-encoding gives the same bytes.
    ASSERT_EQ(encodeSetpoint(dev, out.value().setpoint).value(), frame.value()) << i;
  }
}

TEST(SetpointCodec, RandomPayloadsDecodeAndReencodeExactly) {
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> byte(0, 255), device(0, 63);
  for (int i = 0; i < 20000; ++i) {
    Frame frame;
    frame.id = teamFrameId(kSetpointApiClass, kSetpointApiIndex, static_cast<std::uint8_t>(device(rng)));
    frame.extended = true;
    frame.dlc = 8;
    for (auto& b : frame.data) b = static_cast<std::uint8_t>(byte(rng));
    const auto decoded = decodeSetpoint(frame);
    ASSERT_TRUE(decoded.ok());
    const auto again = encodeSetpoint(decoded.value().device, decoded.value().setpoint);
    ASSERT_TRUE(again.ok()) << i;
    ASSERT_EQ(again.value(), frame) << i;
  }
}

TEST(SetpointCodec, DecodeRejectsWrongFrames) {
  const Frame good = mustEncode(1, Setpoint{0.25, 0.1, 0.2, 3});
  ASSERT_TRUE(decodeSetpoint(good).ok());
  for (std::uint8_t dlc = 0; dlc <= 8; ++dlc) {
    if (dlc == 8) continue;
    Frame frame = good;
    frame.dlc = dlc;
    for (std::uint8_t i = dlc; i < 8; ++i) frame.data[i] = 0;
    ASSERT_EQ(decodeSetpoint(frame).status(), CodecError::kWrongLength) << int{dlc};
  }
  Frame standard = good;
  standard.extended = false;
  standard.id = 0x401;
  EXPECT_EQ(decodeSetpoint(standard).status(), CodecError::kNotExtended);
  Frame remote = good;
  remote.remote = true;
  EXPECT_EQ(decodeSetpoint(remote).status(), CodecError::kRemoteFrame);
  Frame error = good;
  error.error = true;
  EXPECT_EQ(decodeSetpoint(error).status(), CodecError::kErrorFrame);
  Frame status_id = good;
  status_id.id = teamFrameId(kStatusApiClass, kStatusApiIndex, 1);
  EXPECT_EQ(decodeSetpoint(status_id).status(), CodecError::kWrongId);
  Frame other_manufacturer = good;
  other_manufacturer.id = packFrcId(FrcId{10, 5, 1, 0, 1});
  EXPECT_EQ(decodeSetpoint(other_manufacturer).status(), CodecError::kWrongId);
  Frame other_type = good;
  other_type.id = packFrcId(FrcId{2, 8, 1, 0, 1});
  EXPECT_EQ(decodeSetpoint(other_type).status(), CodecError::kWrongId);
  Frame other_index = good;
  other_index.id = packFrcId(FrcId{10, 8, 1, 1, 1});
  EXPECT_EQ(decodeSetpoint(other_index).status(), CodecError::kWrongId);
}

TEST(SetpointCodec, EveryErrorHasText) {
  for (int e = 0; e <= static_cast<int>(CodecError::kWrongLength); ++e) {
    EXPECT_FALSE(toString(static_cast<CodecError>(e)).empty());
    EXPECT_NE(toString(static_cast<CodecError>(e)), "unknown codec error");
  }
}

}  // namespace
}  // namespace cyber::can

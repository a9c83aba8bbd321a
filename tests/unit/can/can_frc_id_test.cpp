#include <gtest/gtest.h>

#include <random>

#include "cyber/can/frc_id.hpp"

namespace cyber::can {
namespace {

TEST(FrcId, PacksTheDesignFormula) {
  // id = (10 << 24) | (8 << 16) | (api << 6) | device, api = (class << 4) | index.
  EXPECT_EQ(teamFrameId(1, 0, 1), 0x0A080401u);
  EXPECT_EQ(teamFrameId(1, 0, 2), 0x0A080402u);
  EXPECT_EQ(teamFrameId(2, 0, 3), 0x0A080803u);
  EXPECT_EQ(apiId(1, 0), 0x10);
  EXPECT_EQ(apiId(2, 0), 0x20);
  EXPECT_EQ(apiId(63, 15), 0x3FF);
}

TEST(FrcId, HeartbeatIdIsTheRoboRiosUniversalHeartbeat) {
  // Robot controller (1), NI (1), API class 6 index 1, device 0.
  EXPECT_EQ(unpackFrcId(kHeartbeatId), (FrcId{1, 1, 6, 1, 0}));
  EXPECT_EQ(packFrcId(FrcId{1, 1, 6, 1, 0}), kHeartbeatId);
}

TEST(FrcId, RandomFieldsRoundTrip) {
  std::mt19937 rng(20250101);
  std::uniform_int_distribution<int> type(0, 31), manufacturer(0, 255), api_class(0, 63), api_index(0, 15),
      device(0, 63);
  for (int i = 0; i < 5000; ++i) {
    const FrcId id{static_cast<std::uint8_t>(type(rng)), static_cast<std::uint8_t>(manufacturer(rng)),
                   static_cast<std::uint8_t>(api_class(rng)), static_cast<std::uint8_t>(api_index(rng)),
                   static_cast<std::uint8_t>(device(rng))};
    const std::uint32_t packed = packFrcId(id);
    ASSERT_EQ(packed & ~0x1FFFFFFFu, 0u);
    ASSERT_EQ(unpackFrcId(packed), id);
  }
}

TEST(FrcId, EveryTwentyNineBitIdUnpacksAndRepacks) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::uint32_t> raw(0, 0x1FFFFFFFu);
  for (int i = 0; i < 5000; ++i) {
    const std::uint32_t id = raw(rng);
    ASSERT_EQ(packFrcId(unpackFrcId(id)), id);
  }
}

}  // namespace
}  // namespace cyber::can

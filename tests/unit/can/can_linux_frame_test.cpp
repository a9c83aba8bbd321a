#include <gtest/gtest.h>

#include <linux/can/error.h>

#include <cstring>
#include <random>

#include "cyber/can/linux_frame.hpp"
#include "random_frame.hpp"

namespace cyber::can {
namespace {

using test::randomFrame;

TEST(LinuxFrame, FlagsAndBytes) {
  Frame frame;
  frame.id = 0x0A080401u;
  frame.extended = true;
  frame.dlc = 3;
  frame.data = {1, 2, 3, 0, 0, 0, 0, 0};
  const can_frame raw = toLinuxFrame(frame);
  EXPECT_EQ(raw.can_id, 0x0A080401u | CAN_EFF_FLAG);
  EXPECT_EQ(raw.len, 3);
  EXPECT_EQ(raw.data[0], 1);
  EXPECT_EQ(raw.data[2], 3);
  EXPECT_EQ(raw.data[3], 0);

  Frame remote;
  remote.id = 0x123;
  remote.remote = true;
  remote.dlc = 4;
  EXPECT_EQ(toLinuxFrame(remote).can_id, 0x123u | CAN_RTR_FLAG);

  Frame error;
  error.error = true;
  error.id = CAN_ERR_BUSOFF;
  error.dlc = 8;
  EXPECT_EQ(toLinuxFrame(error).can_id, CAN_ERR_BUSOFF | CAN_ERR_FLAG);
}

TEST(LinuxFrame, RandomWellFormedFramesRoundTrip) {
  std::mt19937 rng(2024);
  for (int i = 0; i < 20000; ++i) {
    const Frame frame = randomFrame(rng);
    ASSERT_TRUE(isWellFormed(frame));
    const auto back = fromLinuxFrame(toLinuxFrame(frame));
    ASSERT_TRUE(back.ok());
    ASSERT_EQ(back.value(), frame) << i;
  }
}

TEST(LinuxFrame, RejectsLengthAboveEight) {
  can_frame raw;
  std::memset(&raw, 0, sizeof raw);
  raw.can_id = 0x123;
  raw.len = 9;
  EXPECT_EQ(fromLinuxFrame(raw).status(), CodecError::kWrongLength);
}

TEST(LinuxFrame, IgnoresBytesPastLength) {
  can_frame raw;
  std::memset(&raw, 0xAB, sizeof raw);
  raw.can_id = 0x123;
  raw.len = 2;
  const Frame frame = fromLinuxFrame(raw).value();
  EXPECT_TRUE(isWellFormed(frame));
  EXPECT_EQ(frame.data[1], 0xAB);
  EXPECT_EQ(frame.data[2], 0);
}

TEST(Frame, WellFormedness) {
  Frame frame;
  frame.id = 0x800;  // 12 bits in a standard frame
  EXPECT_FALSE(isWellFormed(frame));
  frame.extended = true;
  EXPECT_TRUE(isWellFormed(frame));
  frame.id = 0x20000000u;
  EXPECT_FALSE(isWellFormed(frame));
  frame.id = 1;
  frame.dlc = 9;
  EXPECT_FALSE(isWellFormed(frame));
  frame.dlc = 1;
  frame.data[1] = 5;  // byte past dlc
  EXPECT_FALSE(isWellFormed(frame));
  Frame error;
  error.error = true;
  error.extended = true;
  EXPECT_FALSE(isWellFormed(error));
}

}  // namespace
}  // namespace cyber::can

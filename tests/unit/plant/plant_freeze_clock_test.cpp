// FreezeClock: simulation time without the time the simulator stood still.

#include <gtest/gtest.h>

#include "cyber/plant/freeze_clock.hpp"

namespace cyber::plant {
namespace {

TEST(FreezeClock, RegularWakesKeepRealTime) {
  FreezeClock clock(0.010, 0.020);
  for (int k = 1; k <= 100; ++k) EXPECT_DOUBLE_EQ(clock.onWake(k * 0.010), k * 0.010);
  // Late by less than the tolerance: still real time.
  EXPECT_DOUBLE_EQ(clock.onWake(1.0 + 0.029), 1.029);
  EXPECT_EQ(clock.freezes(), 0);
}

TEST(FreezeClock, AFreezeAdvancesByOneIntervalOnly) {
  FreezeClock clock(0.010, 0.020);
  for (int k = 1; k <= 50; ++k) clock.onWake(k * 0.010);
  EXPECT_EQ(clock.freezes(), 0);
  EXPECT_DOUBLE_EQ(clock.onWake(0.8), 0.51);  // 300 ms without a wake: 290 ms frozen
  EXPECT_EQ(clock.freezes(), 1);
  EXPECT_DOUBLE_EQ(clock.frozenSeconds(), 0.29);
  EXPECT_DOUBLE_EQ(clock.simulationTime(0.805), 0.515);
  EXPECT_DOUBLE_EQ(clock.onWake(0.81), 0.52);
  EXPECT_DOUBLE_EQ(clock.onWake(1.31), 0.53);
  EXPECT_EQ(clock.freezes(), 2);
}

TEST(FreezeClock, SimulationTimeNeverGoesBack) {
  FreezeClock clock(0.010, 0.020);
  double previous = 0.0;
  double real = 0.0;
  for (int k = 1; k < 500; ++k) {
    real += (k % 37 == 0) ? 0.4 : 0.001 * (k % 11);
    const double sim = clock.onWake(real);
    ASSERT_GE(sim, previous);
    ASSERT_LE(sim - previous, std::max(0.010, 0.001 * (k % 11)) + 1e-12);
    previous = sim;
  }
}

}  // namespace
}  // namespace cyber::plant

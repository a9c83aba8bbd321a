#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <thread>

#include "cyber/daemon/io/latency_histogram.hpp"
#include "cyber/daemon/io/latest_value.hpp"
#include "cyber/daemon/io/spsc_ring.hpp"
#include "latest_value_peer.hpp"

namespace cyber::daemon::io {

namespace {

TEST(SpscRing, IsFifoAndRefusesWhenFull) {
  SpscRing<int, 4> ring;
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(ring.push(i));
  EXPECT_FALSE(ring.push(99));
  int value = -1;
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(ring.pop(value));
    EXPECT_EQ(value, i);
  }
  EXPECT_FALSE(ring.pop(value));
}

TEST(SpscRing, DeliversEverythingInOrderAcrossThreads) {
  SpscRing<std::int64_t, 64> ring;
  constexpr std::int64_t kCount = 200000;
  std::thread producer([&] {
    for (std::int64_t i = 0; i < kCount;) {
      if (ring.push(i)) ++i;
    }
  });
  std::int64_t expected = 0, value = 0;
  while (expected < kCount) {
    if (ring.pop(value)) {
      ASSERT_EQ(value, expected);
      ++expected;
    }
  }
  producer.join();
}

struct Pair {
  std::int64_t a = 0;
  std::int64_t b = 0;
  double c = 0.0;
};

// One writer stores 1, 2, ... while `read` takes values from another thread (nothing: try again):
// each one whole, none older than the one before.
template <class Read>
void readWhileWriting(Read read) {
  LatestValue<Pair> latest;
  constexpr std::int64_t kWrites = 200000;
  std::thread writer([&] {
    for (std::int64_t i = 1; i <= kWrites; ++i) latest.store(Pair{i, -i, static_cast<double>(i)});
  });
  std::int64_t last = 0;
  while (last < kWrites) {
    const std::optional<Pair> p = read(latest);
    if (!p) continue;
    ASSERT_EQ(p->a, -p->b);
    ASSERT_EQ(static_cast<double>(p->a), p->c);
    ASSERT_GE(p->a, last);  // never goes back
    last = p->a;
  }
  writer.join();
}

TEST(LatestValue, ReadersNeverSeeATornValue) {
  readWhileWriting([](const LatestValue<Pair>& latest) { return std::optional<Pair>(latest.load()); });
}

TEST(LatestValue, TryLoadNeverGivesATornValue) {
  readWhileWriting([](const LatestValue<Pair>& latest) { return latest.tryLoad(); });
}

// The streamer reads ARM_STATE with tryLoad: a writer stopped in the middle of a store (on one CPU,
// the lower-priority receiver thread the streamer preempted) must not hold the reader up.
TEST(LatestValue, TryLoadGivesNothingWhileAStoreIsUnfinishedAndDoesNotWait) {
  LatestValue<Pair> latest(Pair{1, -1, 1.0});
  ASSERT_TRUE(latest.tryLoad().has_value());
  EXPECT_EQ(latest.tryLoad()->a, 1);
  LatestValueTestPeer<Pair>::beginStore(latest);
  EXPECT_FALSE(latest.tryLoad().has_value());
  EXPECT_FALSE(latest.tryLoad().has_value());
  LatestValueTestPeer<Pair>::endStore(latest);
  ASSERT_TRUE(latest.tryLoad().has_value());
  EXPECT_EQ(latest.tryLoad()->c, 1.0);
  latest.store(Pair{2, -2, 2.0});
  EXPECT_EQ(latest.tryLoad()->a, 2);
}

TEST(LatencyHistogram, PercentilesWithinTheBinWidth) {
  LatencyHistogram h;
  EXPECT_EQ(h.percentileUs(0.5), 0.0);
  for (int i = 1; i <= 1000; ++i) h.record(static_cast<double>(i));
  EXPECT_EQ(h.count(), 1000);
  EXPECT_NEAR(h.percentileUs(0.5), 500.0, 500.0 * 0.02);
  EXPECT_NEAR(h.percentileUs(0.99), 990.0, 990.0 * 0.02);
  EXPECT_DOUBLE_EQ(h.maxUs(), 1000.0);
  EXPECT_LE(h.percentileUs(1.0), 1000.0);
  h.record(0.0);   // below the first bin edge
  h.record(1e12);  // beyond the last: clamped into it
  EXPECT_DOUBLE_EQ(h.maxUs(), 1e12);
}

}  // namespace
}  // namespace cyber::daemon::io

#include "cyber/daemon/io/clock_pair.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace cyber::daemon::io {
namespace {

// A scripted pair of clocks: the wall clock runs 1e15 us ahead of the monotonic one, and each
// attempt's wall read is delayed after the first monotonic read by that attempt's preemption.
struct ScriptedClocks {
  static constexpr std::int64_t kOffsetUs = 1'000'000'000'000'000;
  std::vector<MonoNs> preemptions_ns;
  int reads = 0;
  MonoNs mono = 5'000'000'000;
  int attempt = 0;
};
ScriptedClocks* scripted = nullptr;

MonoNs scriptedMono() {
  // Every read costs 1 us; the wall read of each attempt comes after its preemption.
  scripted->mono += 1'000;
  return scripted->mono;
}
std::int64_t scriptedWall() {
  const auto& p = scripted->preemptions_ns;
  scripted->mono += p[static_cast<size_t>(std::min<int>(scripted->attempt, static_cast<int>(p.size()) - 1))];
  ++scripted->attempt;
  scripted->mono += 1'000;
  return ScriptedClocks::kOffsetUs + scripted->mono / 1000;
}

ClockPair readScripted(std::vector<MonoNs> preemptions_ns, int* attempts) {
  ScriptedClocks clocks;
  clocks.preemptions_ns = std::move(preemptions_ns);
  scripted = &clocks;
  const ClockPair pair = readClockPair(ClockReaders{&scriptedMono, &scriptedWall});
  scripted = nullptr;
  *attempts = clocks.attempt;
  return pair;
}

TEST(ClockPair, AnUnpreemptedReadIsTakenAtOnceAndConvertsWithinItsBracket) {
  int attempts = 0;
  const ClockPair pair = readScripted({0}, &attempts);
  EXPECT_EQ(attempts, 1);
  EXPECT_LE(pair.bracket_ns, kClockPairBracketNs);
  // The true offset is kOffsetUs: the conversion is off by at most half the bracket.
  const MonoNs t = 7'000'000'000;
  EXPECT_NEAR(static_cast<double>(wallMicrosAt(t, pair)), static_cast<double>(ScriptedClocks::kOffsetUs + t / 1000),
              pair.bracket_ns / 2000.0 + 1.0);
}

TEST(ClockPair, APreemptionBetweenTheReadsIsReadAgainNotStampedLate) {
  // The first attempt is preempted for 40 ms between its monotonic and wall reads: two plain
  // reads would stamp every time 40 ms late.
  int attempts = 0;
  const ClockPair pair = readScripted({40'000'000, 0}, &attempts);
  EXPECT_EQ(attempts, 2);
  const MonoNs t = 9'000'000'000;
  EXPECT_NEAR(static_cast<double>(wallMicrosAt(t, pair)), static_cast<double>(ScriptedClocks::kOffsetUs + t / 1000),
              3.0);
}

TEST(ClockPair, WhenEveryAttemptIsPreemptedTheTightestIsKept) {
  int attempts = 0;
  const ClockPair pair = readScripted({30'000'000, 5'000'000, 20'000'000, 9'000'000}, &attempts);
  EXPECT_EQ(attempts, kClockPairAttempts);
  EXPECT_EQ(pair.bracket_ns, 5'000'000 + 2'000);
}

TEST(ClockPair, TheRealClocksAgreeWithAWallReadBetweenTwoMonotonicReads) {
  const ClockPair pair = readClockPair();
  EXPECT_GE(pair.bracket_ns, 0);
  EXPECT_GT(pair.wall_us, 1'500'000'000'000'000);  // after 2017: a real wall clock
}

}  // namespace
}  // namespace cyber::daemon::io

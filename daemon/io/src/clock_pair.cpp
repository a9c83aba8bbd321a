#include "cyber/daemon/io/clock_pair.hpp"

#include "cyber/daemon/io/lcm_messages.hpp"
#include "cyber/daemon/io/monotonic_clock.hpp"

namespace cyber::daemon::io {

ClockPair readClockPair(const ClockReaders& readers) {
  ClockPair best;
  for (int attempt = 0; attempt < kClockPairAttempts; ++attempt) {
    const MonoNs before = readers.mono_ns();
    const std::int64_t wall = readers.wall_us();
    const MonoNs after = readers.mono_ns();
    const ClockPair pair{before + (after - before) / 2, wall, after - before};
    if (attempt == 0 || pair.bracket_ns < best.bracket_ns) best = pair;
    if (best.bracket_ns <= kClockPairBracketNs) break;
  }
  return best;
}

ClockPair readClockPair() { return readClockPair(ClockReaders{&monotonicNow, &wallMicros}); }

std::int64_t wallMicrosAt(MonoNs t, const ClockPair& clocks) { return clocks.wall_us + (t - clocks.mono_ns) / 1000; }

}  // namespace cyber::daemon::io

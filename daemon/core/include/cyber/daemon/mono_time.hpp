#pragma once
// Daemon time: CLOCK_MONOTONIC in integer nanoseconds (what timerfd and epoll deadlines use).
// Plain integers so they fit in atomics and seqlocks; the logic takes "now" as a parameter so tests
// drive it with a fake clock. Only daemon/io reads the real clock (monotonic_clock.hpp).

#include <cmath>
#include <cstdint>
#include <limits>

namespace cyber::daemon {

using MonoNs = std::int64_t;
inline constexpr MonoNs kNever = std::numeric_limits<MonoNs>::min();

inline MonoNs secondsToNs(double seconds) { return static_cast<MonoNs>(std::llround(seconds * 1e9)); }
inline double nsToSeconds(MonoNs ns) { return static_cast<double>(ns) * 1e-9; }
inline double nsToMs(MonoNs ns) { return static_cast<double>(ns) * 1e-6; }

}  // namespace cyber::daemon

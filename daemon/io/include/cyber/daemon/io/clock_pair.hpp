#pragma once
// One reading of CLOCK_MONOTONIC and CLOCK_REALTIME taken together, for stamping a monotonic
// time as LCM utime. Two plain reads in a row are skewed by however long the thread is
// preempted between them: the event loop is a normal thread, so on one busy CPU a SCHED_FIFO
// tick and the other normal threads can come between the reads for tens of milliseconds, and
// ARM_TRAJECTORY's start_utime is then late by as much (docs/lcm.md, "Times").

#include <cstdint>

#include "cyber/daemon/mono_time.hpp"

namespace cyber::daemon::io {

struct ClockPair {
  MonoNs mono_ns = 0;
  std::int64_t wall_us = 0;
  // How far apart the two monotonic reads that bracket the wall read were: the pair's error bound.
  MonoNs bracket_ns = 0;
};

struct ClockReaders {
  MonoNs (*mono_ns)();
  std::int64_t (*wall_us)();
};

// A bracket this short means the wall read was not preempted.
inline constexpr MonoNs kClockPairBracketNs = 20'000;
inline constexpr int kClockPairAttempts = 4;

// Reads monotonic, wall, monotonic until the bracket is within kClockPairBracketNs, at most
// kClockPairAttempts times; returns the tightest pair seen (mono_ns the bracket's middle).
ClockPair readClockPair(const ClockReaders& readers);
// The real clocks.
ClockPair readClockPair();

// A monotonic time as wall-clock microseconds, through the offset the pair recorded.
std::int64_t wallMicrosAt(MonoNs t, const ClockPair& clocks);

}  // namespace cyber::daemon::io

#pragma once
// The machine's own timer latency: a bare SCHED_FIFO thread on a periodic timerfd, measured the
// way the daemon's streamer measures itself (wake-up minus scheduled time; expirations beyond one
// are missed periods). The yardstick for the streamer's jitter and overruns (docs/performance.md,
// docs/testing.md "Soak").

#include <atomic>
#include <cstdint>

#include "cyber/daemon/io/latency_histogram.hpp"
#include "cyber/daemon/mono_time.hpp"

namespace cyber::test {

struct BareTimerResult {
  daemon::io::LatencyHistogram jitter;
  std::atomic<std::int64_t> overruns{0};
  std::atomic<bool> realtime{false};  // SCHED_FIFO granted
};

// Runs the timer on a new thread at `priority` for `seconds` (or until `stop` turns true) and
// returns when it is done.
void measureBareTimer(double seconds, daemon::MonoNs period_ns, int priority, BareTimerResult& out,
                      const std::atomic<bool>* stop = nullptr);

}  // namespace cyber::test

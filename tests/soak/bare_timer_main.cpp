// cyber-bare-timer --seconds S [--rate HZ] [--priority P]: the machine's own timer latency for as
// long as a soak runs (tools/soak), measured as the daemon's streamer measures itself
// (tests/support/bare_timer.hpp). Stops early on SIGTERM/SIGINT. Prints key=value lines.

#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "bare_timer.hpp"

int main(int argc, char** argv) {
  double seconds = 10.0, rate_hz = 200.0;
  int priority = 50;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string arg = argv[i];
    if (arg == "--seconds")
      seconds = std::atof(argv[i + 1]);
    else if (arg == "--rate")
      rate_hz = std::atof(argv[i + 1]);
    else if (arg == "--priority")
      priority = std::atoi(argv[i + 1]);
    else
      argc = -1;
  }
  if (argc < 0 || argc % 2 == 0 || !(seconds > 0.0) || !(rate_hz > 0.0)) {
    std::fprintf(stderr, "usage: cyber-bare-timer --seconds S [--rate HZ] [--priority P]\n");
    return 2;
  }
  // SIGTERM/SIGINT through sigwait on a helper thread, so the timer thread is never interrupted.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGTERM);
  sigaddset(&signals, SIGINT);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  std::atomic<bool> stop{false};
  std::thread waiter([&] {
    int signal = 0;
    sigwait(&signals, &signal);
    stop.store(true);
  });
  waiter.detach();

  cyber::test::BareTimerResult result;
  const auto period_ns = static_cast<cyber::daemon::MonoNs>(1e9 / rate_hz);
  cyber::test::measureBareTimer(seconds, period_ns, priority, result, &stop);
  std::printf(
      "bare_ticks=%lld\nbare_overruns=%lld\nbare_jitter_p50_us=%.1f\nbare_jitter_p99_us=%.1f\n"
      "bare_jitter_max_us=%.1f\nbare_sched_fifo=%d\n",
      static_cast<long long>(result.jitter.count()), static_cast<long long>(result.overruns.load()),
      result.jitter.percentileUs(0.5), result.jitter.percentileUs(0.99), result.jitter.maxUs(),
      result.realtime.load() ? 1 : 0);
  return 0;
}

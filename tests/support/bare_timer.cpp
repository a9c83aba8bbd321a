#include "bare_timer.hpp"

#include <sys/prctl.h>
#include <pthread.h>
#include <sched.h>

#include <thread>

#include "cyber/daemon/io/fd.hpp"
#include "cyber/daemon/io/monotonic_clock.hpp"

namespace cyber::test {

void measureBareTimer(double seconds, daemon::MonoNs period_ns, int priority, BareTimerResult& out,
                      const std::atomic<bool>* stop) {
  std::thread thread([&] {
    sched_param param{};
    param.sched_priority = priority;
    if (pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0) out.realtime.store(true);
    prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
    daemon::io::TimerFd timer(true);
    daemon::MonoNs scheduled = (daemon::io::monotonicNow() / period_ns + 1) * period_ns;
    const daemon::MonoNs end = scheduled + static_cast<daemon::MonoNs>(seconds * 1e9);
    timer.startPeriodic(scheduled, period_ns);
    while (scheduled < end && (stop == nullptr || !stop->load())) {
      const std::uint64_t expirations = timer.wait();
      const daemon::MonoNs now = daemon::io::monotonicNow();
      scheduled += static_cast<daemon::MonoNs>(expirations - 1) * period_ns;
      out.jitter.record(daemon::nsToSeconds(now - scheduled) * 1e6);
      if (expirations > 1) out.overruns.fetch_add(static_cast<std::int64_t>(expirations - 1));
      scheduled += period_ns;
    }
  });
  thread.join();
}

}  // namespace cyber::test

#include "cyber/daemon/io/monotonic_clock.hpp"

#include <time.h>

namespace cyber::daemon::io {

MonoNs monotonicNow() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<MonoNs>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

}  // namespace cyber::daemon::io

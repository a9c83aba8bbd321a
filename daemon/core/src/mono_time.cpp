#include "cyber/daemon/mono_time.hpp"

#include <time.h>

namespace cyber::daemon {

MonoNs monotonicNow() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<MonoNs>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

}  // namespace cyber::daemon

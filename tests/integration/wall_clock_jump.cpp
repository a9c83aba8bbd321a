// LD_PRELOAD shim for the wall_clock_jump integration case: the wall clock (CLOCK_REALTIME, which
// std::chrono::system_clock and spdlog read through clock_gettime) of the process it is loaded into jumps
// every CYBER_WALL_JUMP_PERIOD_S seconds (default 0.5) through the offsets 0, +1 h, -1 h,
// +1 year, and again. Monotonic clocks are untouched. The daemon must not notice (it measures
// every age and period on CLOCK_MONOTONIC; wall time only stamps messages).

#include <dlfcn.h>
#include <time.h>

#include <cstdint>
#include <cstdlib>

namespace {

using ClockGettime = int (*)(clockid_t, timespec*);

ClockGettime realClockGettime() {
  static const auto real = reinterpret_cast<ClockGettime>(dlsym(RTLD_NEXT, "clock_gettime"));
  return real;
}

std::int64_t monotonicNs() {
  timespec ts{};
  realClockGettime()(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

std::int64_t wallOffsetNs() {
  static const double period_s = [] {
    const char* text = std::getenv("CYBER_WALL_JUMP_PERIOD_S");
    const double value = text != nullptr ? std::atof(text) : 0.5;
    return value > 0.0 ? value : 0.5;
  }();
  static const std::int64_t start_ns = monotonicNs();
  constexpr std::int64_t kHourNs = 3600LL * 1'000'000'000;
  constexpr std::int64_t kOffsetsNs[] = {0, kHourNs, -kHourNs, 365 * 24 * kHourNs};
  const auto step = static_cast<std::int64_t>(static_cast<double>(monotonicNs() - start_ns) * 1e-9 / period_s);
  return kOffsetsNs[step % 4];
}

void shift(timespec& ts, std::int64_t offset_ns) {
  const std::int64_t ns = static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec + offset_ns;
  ts.tv_sec = static_cast<time_t>(ns / 1'000'000'000);
  ts.tv_nsec = static_cast<long>(ns % 1'000'000'000);
}

}  // namespace

extern "C" int clock_gettime(clockid_t clock, timespec* ts) {
  const int rc = realClockGettime()(clock, ts);
  if (rc == 0 && (clock == CLOCK_REALTIME || clock == CLOCK_REALTIME_COARSE)) shift(*ts, wallOffsetNs());
  return rc;
}

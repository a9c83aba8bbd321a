#pragma once
// Keeps a repeating problem to one log line per interval: the first occurrence is logged, the
// rest are counted and summarised with the next line that is let through.

#include <spdlog/spdlog.h>

#include <cstdint>
#include <string>
#include <utility>

#include "cyber/daemon/mono_time.hpp"

namespace cyber::daemon::io {

class LogThrottle {
 public:
  explicit LogThrottle(double interval_s = 1.0) : interval_ns_(secondsToNs(interval_s)) {}

  // True when this occurrence should be logged; `suppressed` then holds how many were not.
  bool allow(MonoNs now, std::int64_t& suppressed) {
    if (last_ns_ != kNever && now - last_ns_ < interval_ns_) {
      ++suppressed_;
      return false;
    }
    last_ns_ = now;
    suppressed = suppressed_;
    suppressed_ = 0;
    return true;
  }

 private:
  MonoNs interval_ns_;
  MonoNs last_ns_ = kNever;
  std::int64_t suppressed_ = 0;
};

// A warning that may repeat, logged through a LogThrottle: "<text> (N more since the last report)".
class ThrottledWarning {
 public:
  explicit ThrottledWarning(double interval_s = 1.0) : throttle_(interval_s) {}

  template <class... Args>
  void warn(MonoNs now, fmt::format_string<Args...> format, Args&&... args) {
    std::int64_t suppressed = 0;
    if (!throttle_.allow(now, suppressed)) return;
    const std::string text = fmt::format(format, std::forward<Args>(args)...);
    if (suppressed > 0) {
      spdlog::warn("{} ({} more since the last report)", text, suppressed);
    } else {
      spdlog::warn("{}", text);
    }
  }

 private:
  LogThrottle throttle_;
};

}  // namespace cyber::daemon::io

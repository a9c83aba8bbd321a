#pragma once
// Keeps a repeating problem to one log line per interval: the first occurrence is logged, the
// rest are counted and summarised with the next line that is let through.

#include <cstdint>

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

}  // namespace cyber::daemon::io

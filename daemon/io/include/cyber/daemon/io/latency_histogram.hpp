#pragma once
// Percentiles of durations without storing samples: logarithmic bins 2% wide from 1 us to ~100 s.
// One thread records (relaxed atomics, no allocation), any thread reads.

#include <array>
#include <atomic>
#include <cstdint>

namespace cyber::daemon::io {

class LatencyHistogram {
 public:
  static constexpr int kBins = 940;  // 1.02^940 us ~ 1.2e8 us

  void record(double microseconds);
  // The value below which `fraction` of the samples lie (upper edge of that bin), 0 when empty.
  [[nodiscard]] double percentileUs(double fraction) const;
  [[nodiscard]] double maxUs() const;
  [[nodiscard]] std::int64_t count() const { return count_.load(std::memory_order_relaxed); }

 private:
  std::array<std::atomic<std::int64_t>, kBins> bins_{};
  std::atomic<std::int64_t> count_{0};
  std::atomic<double> max_us_{0.0};
};

}  // namespace cyber::daemon::io

#include "cyber/daemon/io/latency_histogram.hpp"

#include <algorithm>
#include <cmath>

namespace cyber::daemon::io {

namespace {

constexpr double kGrowth = 1.02;

int binOf(double microseconds) {
  if (!(microseconds > 1.0)) return 0;
  const int bin = static_cast<int>(std::ceil(std::log(microseconds) / std::log(kGrowth)));
  return std::clamp(bin, 0, LatencyHistogram::kBins - 1);
}

}  // namespace

void LatencyHistogram::record(double microseconds) {
  bins_[static_cast<size_t>(binOf(microseconds))].fetch_add(1, std::memory_order_relaxed);
  count_.fetch_add(1, std::memory_order_relaxed);
  if (microseconds > max_us_.load(std::memory_order_relaxed)) max_us_.store(microseconds, std::memory_order_relaxed);
}

double LatencyHistogram::percentileUs(double fraction) const {
  const std::int64_t total = count();
  if (total == 0) return 0.0;
  const auto rank = static_cast<std::int64_t>(std::ceil(std::clamp(fraction, 0.0, 1.0) * static_cast<double>(total)));
  std::int64_t seen = 0;
  for (int i = 0; i < kBins; ++i) {
    seen += bins_[static_cast<size_t>(i)].load(std::memory_order_relaxed);
    if (seen >= std::max<std::int64_t>(rank, 1)) return std::min(std::pow(kGrowth, i), std::max(1.0, maxUs()));
  }
  return maxUs();
}

double LatencyHistogram::maxUs() const { return max_us_.load(std::memory_order_relaxed); }

}  // namespace cyber::daemon::io

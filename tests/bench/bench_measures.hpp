#pragma once
// What every planner benchmark reports: a distribution's median / p90 / p99 / max as counters, and
// the calling thread's CPU time (on a shared machine wall-clock times also measure the other
// programs; docs/performance.md).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <string>
#include <vector>

namespace cyber::bench {

// The nearest-rank p-quantile of v (0 for an empty v).
inline double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(p * static_cast<double>(v.size() - 1) + 0.5))];
}

// Counters PREFIX_median_ms, PREFIX_p90_ms, PREFIX_p99_ms, PREFIX_max_ms (median_ms, ... without
// a prefix).
inline void reportMs(benchmark::State& state, const std::string& prefix, const std::vector<double>& ms) {
  const std::string head = prefix.empty() ? "" : prefix + "_";
  state.counters[head + "median_ms"] = percentile(ms, 0.5);
  state.counters[head + "p90_ms"] = percentile(ms, 0.9);
  state.counters[head + "p99_ms"] = percentile(ms, 0.99);
  state.counters[head + "max_ms"] = percentile(ms, 1.0);
}

// CPU time of the calling thread, in ms.
inline double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

}  // namespace cyber::bench

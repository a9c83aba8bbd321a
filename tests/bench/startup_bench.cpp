// The daemon's start-up per shipped robot (config/*.toml): its configuration loaded and
// MotionPlanner::create with every grid, as cyber-plannerd does it, through the grid cache.
// cold: an empty cache folder (every grid built, on two threads, and stored); warm: the folder of
// the start before (every grid read and checked); none: no cache (built, nothing stored).
// Wall time (the target: docs/performance.md, "Start-up"), the process's CPU time of all its threads,
// and the calling thread's: beside the other's share, what the wall time of an idle two-core machine
// would be, which a loaded machine's wall time does not show.

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bench_measures.hpp"
#include "cyber/config/load_config.hpp"
#include "cyber/planner/motion_planner.hpp"
#include "shipped_robots.hpp"

namespace cyber::planner {
namespace {

namespace fs = std::filesystem;

enum class Cache { kCold, kWarm, kNone };

double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

void startUp(const std::string& config_file, const std::optional<fs::path>& dir) {
  const config::Config config = config::loadConfigFile(config_file);
  benchmark::DoNotOptimize(MotionPlanner::create(config.robot, GridSelection{}, dir).ok());
}

void BM_StartUp(benchmark::State& state, const std::string& robot, Cache cache) {
  const std::string config_file = std::string(CYBER_SOURCE_DIR) + "/config/" + robot + ".toml";
  std::string pattern = (fs::temp_directory_path() / "cyber-startup-bench-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    state.SkipWithError("no temporary folder");
    return;
  }
  const fs::path dir = pattern;
  if (cache == Cache::kWarm) startUp(config_file, dir);
  std::vector<double> wall_ms, cpu_ms, thread_cpu_ms;
  for (auto _ : state) {
    if (cache == Cache::kCold) {
      state.PauseTiming();
      fs::remove_all(dir);
      state.ResumeTiming();
    }
    const double cpu0 = processCpuMs();
    const double thread_cpu0 = bench::threadCpuMs();
    const auto t0 = std::chrono::steady_clock::now();
    startUp(config_file, cache == Cache::kNone ? std::nullopt : std::optional<fs::path>(dir));
    wall_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    cpu_ms.push_back(processCpuMs() - cpu0);
    thread_cpu_ms.push_back(bench::threadCpuMs() - thread_cpu0);
  }
  fs::remove_all(dir);
  bench::reportMs(state, "wall", wall_ms);
  state.counters["cpu_median_ms"] = bench::percentile(cpu_ms, 0.5);
  state.counters["thread_cpu_median_ms"] = bench::percentile(thread_cpu_ms, 0.5);
}

const bool kRegistered = [] {
  for (const char* robot : test::kShippedRobotNames) {
    for (const auto& [name, cache] :
         {std::pair{"cold", Cache::kCold}, std::pair{"warm", Cache::kWarm}, std::pair{"none", Cache::kNone}}) {
      benchmark::RegisterBenchmark((std::string("BM_StartUp/") + name + "/" + robot).c_str(), BM_StartUp,
                                   std::string(robot), cache)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(3);
    }
  }
  return true;
}();

}  // namespace
}  // namespace cyber::planner

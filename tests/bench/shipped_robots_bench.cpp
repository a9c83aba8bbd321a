// Whole-plan speed per shipped robot (config/*.toml): every ordered pair of the named poses of each
// pose set, with that set's pieces, planned `kRepetitions` times; median / p90 / p99 / max of
// MotionPlanner::plan's total and of the thread's CPU time, and the start-up (MotionPlanner::create
// with every grid, as the daemon builds them). docs/performance.md, "Per robot".

#include <benchmark/benchmark.h>

#include <chrono>
#include <string>
#include <vector>

#include "bench_measures.hpp"
#include "cyber/config/load_config.hpp"
#include "cyber/planner/motion_planner.hpp"
#include "shipped_robots.hpp"

namespace cyber::planner {
namespace {

constexpr int kRepetitions = 3;

void BM_ShippedRobotMoves(benchmark::State& state, const std::string& robot) {
  const config::Config config = config::loadConfigFile(std::string(CYBER_SOURCE_DIR) + "/config/" + robot + ".toml");
  const auto t0 = std::chrono::steady_clock::now();
  const auto planner = MotionPlanner::create(config.robot);
  const double create_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (!planner) {
    state.SkipWithError("MotionPlanner::create failed");
    return;
  }
  std::vector<double> total_ms, cpu_ms;
  int planned = 0, refused = 0;
  for (auto _ : state) {
    for (int r = 0; r < kRepetitions; ++r) {
      for (const test::NamedMove& move : test::namedMoves(config)) {
        const double cpu0 = bench::threadCpuMs();
        const auto plan = planner.value().plan(move.request);
        cpu_ms.push_back(bench::threadCpuMs() - cpu0);
        if (!plan) {
          refused += r == 0 ? 1 : 0;
          continue;
        }
        planned += r == 0 ? 1 : 0;
        total_ms.push_back(plan.value().times_ms.total);
      }
    }
  }
  bench::reportMs(state, "total", total_ms);
  bench::reportMs(state, "cpu", cpu_ms);
  state.counters["create_ms"] = create_ms;
  state.counters["planned_moves"] = planned;
  state.counters["refused_moves"] = refused;
}

const bool kRegistered = [] {
  for (const char* robot : test::kShippedRobotNames) {
    benchmark::RegisterBenchmark((std::string("BM_ShippedRobotMoves/") + robot).c_str(), BM_ShippedRobotMoves,
                                 std::string(robot))
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  }
  return true;
}();

}  // namespace
}  // namespace cyber::planner

// Whole-plan speed on the public moves: path (search + smoothing + spline), TOPP, and the total
// of MotionPlanner::plan, as median / p90 / p99 / max over every move and repetition. Also the
// start-up cost (MotionPlanner::create builds the grids of every scene and piece set).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "cyber/planner/motion_planner.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"

namespace cyber::planner {
namespace {

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t i = std::min(v.size() - 1, static_cast<size_t>(p * static_cast<double>(v.size() - 1) + 0.5));
  return v[i];
}

void report(benchmark::State& state, const char* name, const std::vector<double>& v) {
  state.counters[std::string(name) + "_median_ms"] = percentile(v, 0.5);
  state.counters[std::string(name) + "_p90_ms"] = percentile(v, 0.9);
  state.counters[std::string(name) + "_p99_ms"] = percentile(v, 0.99);
  state.counters[std::string(name) + "_max_ms"] = percentile(v, 1.0);
}

void BM_PlannerCreate(benchmark::State& state) {
  for (auto _ : state) {
    auto planner = MotionPlanner::create(test::referenceModel());
    benchmark::DoNotOptimize(planner);
  }
}
BENCHMARK(BM_PlannerCreate)->Unit(benchmark::kMillisecond)->Iterations(3);

// One iteration plans every public move `repetitions` times; the counters carry the distribution.
void BM_PublicMoves(benchmark::State& state) {
  const auto planner = MotionPlanner::create(test::referenceModel());
  const int repetitions = static_cast<int>(state.range(0));
  std::vector<double> path_ms, topp_ms, total_ms, wall_ms;
  int planned = 0, no_path = 0, failed = 0;
  for (auto _ : state) {
    for (int r = 0; r < repetitions; ++r) {
      for (const test::PublicMove& move : test::publicMoves()) {
        PlanRequest request;
        request.start = move.from;
        request.goal = move.to;
        request.pieces = move.pieces;
        const auto t0 = std::chrono::steady_clock::now();
        const auto plan = planner.value().plan(request);
        const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        if (!plan) {
          (plan.status() == PlanStatus::kNoPath ? no_path : failed) += r == 0 ? 1 : 0;
          continue;
        }
        planned += r == 0 ? 1 : 0;
        const StageTimesMs& t = plan.value().times_ms;
        path_ms.push_back(t.search + t.smooth);
        topp_ms.push_back(t.topp);
        total_ms.push_back(t.total);
        wall_ms.push_back(wall);
      }
    }
  }
  report(state, "path", path_ms);
  report(state, "topp", topp_ms);
  report(state, "total", total_ms);
  state.counters["planned_moves"] = planned;
  state.counters["no_path_moves"] = no_path;
  state.counters["failed_moves"] = failed;
}
BENCHMARK(BM_PublicMoves)->Arg(5)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace cyber::planner

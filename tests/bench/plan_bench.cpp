// Whole-plan speed on the public moves: path (search + smoothing + spline), TOPP, and the total
// of MotionPlanner::plan, as median / p90 / p99 / max over every move and repetition. Also the
// start-up cost (MotionPlanner::create builds the grids of every scene and piece set).

#include <benchmark/benchmark.h>

#include <chrono>
#include <vector>

#include "bench_measures.hpp"
#include "cyber/planner/motion_planner.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"

namespace cyber::planner {
namespace {

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
  std::vector<double> path_ms, topp_ms, total_ms, wall_ms, cpu_ms;
  int planned = 0, no_path = 0, failed = 0;
  for (auto _ : state) {
    for (int r = 0; r < repetitions; ++r) {
      for (const test::PublicMove& move : test::publicMoves()) {
        PlanRequest request;
        request.start = move.from;
        request.goal = move.to;
        request.pieces = move.pieces;
        const auto t0 = std::chrono::steady_clock::now();
        const double cpu0 = bench::threadCpuMs();
        const auto plan = planner.value().plan(request);
        cpu_ms.push_back(bench::threadCpuMs() - cpu0);
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
  bench::reportMs(state, "path", path_ms);
  bench::reportMs(state, "topp", topp_ms);
  bench::reportMs(state, "total", total_ms);
  bench::reportMs(state, "cpu", cpu_ms);
  state.counters["planned_moves"] = planned;
  state.counters["no_path_moves"] = no_path;
  state.counters["failed_moves"] = failed;
}
BENCHMARK(BM_PublicMoves)->Arg(5)->Unit(benchmark::kMillisecond)->Iterations(1);

// Moving starts as the daemon makes them when a new goal arrives mid-move (a splice): from the
// state a public move's trajectory has at `percent` % of its duration, to the next move's goal.
void BM_SpliceMoves(benchmark::State& state) {
  const auto planner = MotionPlanner::create(test::referenceModel());
  const double fraction = static_cast<double>(state.range(0)) / 100.0;
  const std::vector<test::PublicMove>& moves = test::publicMoves();
  std::vector<std::shared_ptr<const Trajectory>> rides;
  for (const test::PublicMove& move : moves) {
    PlanRequest request;
    request.start = move.from;
    request.goal = move.to;
    request.pieces = move.pieces;
    const auto plan = planner.value().plan(request);
    rides.push_back(plan ? plan.value().trajectory : nullptr);
  }
  std::vector<double> total_ms, cpu_ms;
  int planned = 0, failed = 0;
  for (auto _ : state) {
    for (size_t i = 0; i < moves.size(); ++i) {
      if (!rides[i]) continue;
      const TrajectorySample now = rides[i]->sample(fraction * rides[i]->duration_s());
      PlanRequest request;
      request.start = now.q;
      request.start_velocity = now.qdot;
      request.goal = moves[(i + 1) % moves.size()].to;
      request.pieces = moves[i].pieces;
      const double cpu0 = bench::threadCpuMs();
      const auto plan = planner.value().plan(request);
      cpu_ms.push_back(bench::threadCpuMs() - cpu0);
      if (!plan) {
        failed += plan.status() == PlanStatus::kNoPath ? 0 : 1;
        continue;
      }
      ++planned;
      total_ms.push_back(plan.value().times_ms.total);
    }
  }
  bench::reportMs(state, "total", total_ms);
  bench::reportMs(state, "cpu", cpu_ms);
  state.counters["planned_moves"] = planned;
  state.counters["failed_moves"] = failed;
}
BENCHMARK(BM_SpliceMoves)->Arg(30)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace cyber::planner

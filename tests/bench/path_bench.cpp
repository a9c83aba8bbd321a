// The path stage on the reference robot: grid build per game-piece set, and search + optimisation
// + spline + clearance check per public move (median, p90 and max over the moves).
// Targets (docs/performance.md): grid build <= 200 ms per set, path median <= 3 ms per move.

#include <chrono>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench_measures.hpp"
#include "path/cspace_grid.hpp"
#include "path/path_planner.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"

namespace {

using cyber::planner::CollisionWorld;
using cyber::planner::CSpaceGrid;
using cyber::planner::HeldPieces;
using cyber::planner::PathPlanner;

const cyber::planner::RobotModel& model() { return cyber::test::referenceModel(); }

void BM_GridBuild(benchmark::State& state) {
  const HeldPieces pieces = HeldPieces::fromIndex(static_cast<int>(state.range(0)));
  int blocked = 0;
  for (auto _ : state) {
    const CollisionWorld world(model(), model().scenes.front(), pieces);
    const CSpaceGrid grid = CSpaceGrid::build(world, model());
    blocked = grid.blockedCount();
    benchmark::DoNotOptimize(blocked);
  }
  state.counters["blocked_nodes"] = blocked;
  state.SetLabel(pieces.index() == 0 ? "none" : pieces.index() == 1 ? "coral" : pieces.index() == 2 ? "algae" : "both");
}
BENCHMARK(BM_GridBuild)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

// One iteration plans every public move once; counters report per-move statistics over all
// iterations (wall clock and thread CPU time per plan() call, and the planner's own stage times).
// Argument 0: the reference configuration as loaded; 1: the code's default smoothing settings.
void BM_PathPublicMoves(benchmark::State& state) {
  static const PathPlanner as_loaded(model(), model().scenes.front());
  static const PathPlanner with_defaults = [] {
    cyber::planner::RobotModel m = model();
    m.planner.smoothing = cyber::planner::SmoothingSettings{};
    return PathPlanner(m, m.scenes.front());
  }();
  const PathPlanner& planner = state.range(0) == 0 ? as_loaded : with_defaults;
  const auto& moves = cyber::test::publicMoves();
  std::vector<double> total_ms, cpu_ms, search_ms, smooth_ms;
  int planned = 0, refused = 0;
  for (auto _ : state) {
    planned = refused = 0;
    for (const auto& move : moves) {
      const double c0 = cyber::bench::threadCpuMs();
      const auto t0 = std::chrono::steady_clock::now();
      const auto result = planner.plan(move.from, move.to, move.pieces);
      total_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      cpu_ms.push_back(cyber::bench::threadCpuMs() - c0);
      if (result.ok()) {
        ++planned;
        search_ms.push_back(result.value().search_ms);
        smooth_ms.push_back(result.value().smooth_ms);
      } else {
        ++refused;
      }
      benchmark::DoNotOptimize(result);
    }
  }
  cyber::bench::reportMs(state, "move", total_ms);
  cyber::bench::reportMs(state, "cpu", cpu_ms);
  state.counters["search_median_ms"] = cyber::bench::percentile(search_ms, 0.5);
  state.counters["smooth_median_ms"] = cyber::bench::percentile(smooth_ms, 0.5);
  state.counters["planned"] = planned;
  state.counters["no_path"] = refused;
}
BENCHMARK(BM_PathPublicMoves)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

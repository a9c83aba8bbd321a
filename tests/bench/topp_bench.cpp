// Time-optimal parameterisation speed (algorithm.md section 3). Target (the issue): median
// <= 2 ms per public move for the whole ToppSolver::solve (grid, reachability warm start,
// multiplier estimate, augmented Lagrangian, 1 ms limit check and any refinement).
//
// BM_ToppPublicMoves: the paths of the public moves are planned once (PathPlanner on the
// reference robot); each iteration parameterises every one of them and the counters give the
// median, p90 and max per move over all iterations.

#include <algorithm>
#include <array>
#include <chrono>
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>

#include "../unit/planner/timing/topp_fixtures.hpp"
#include "bench_measures.hpp"
#include "path/path_planner.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"
#include "timing/topp.hpp"
#include "timing/topp_augmented_lagrangian.hpp"
#include "timing/topp_reachability.hpp"

namespace cyber::planner {
namespace {

const std::vector<std::shared_ptr<const GeometricPath>>& publicPaths() {
  static const std::vector<std::shared_ptr<const GeometricPath>> paths = [] {
    const RobotModel& model = test::referenceModel();
    const PathPlanner planner(model, model.scenes.front());
    std::vector<std::shared_ptr<const GeometricPath>> out;
    for (const auto& move : test::publicMoves()) {
      const auto planned = planner.plan(move.from, move.to, move.pieces);
      if (planned.ok()) out.push_back(planned.value().path);
    }
    return out;
  }();
  return paths;
}

void BM_ToppPublicMoves(benchmark::State& state) {
  const RobotModel& model = test::referenceModel();
  const auto& paths = publicPaths();
  ToppSolver solver(model.planner.topp);
  std::vector<double> ms, cpu_ms, refinements;
  int failed = 0;
  for (auto _ : state) {
    failed = 0;
    for (const auto& path : paths) {
      ToppReport report;
      const auto t0 = std::chrono::steady_clock::now();
      const double c0 = bench::threadCpuMs();
      const auto result = solver.solve(path, model.driveModel({}), 0.0, &report);
      cpu_ms.push_back(bench::threadCpuMs() - c0);
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      refinements.push_back(report.refinements);
      if (!result.ok()) ++failed;
      benchmark::DoNotOptimize(result);
    }
  }
  state.counters["moves"] = static_cast<double>(paths.size());
  state.counters["failed"] = failed;
  bench::reportMs(state, "", ms);
  bench::reportMs(state, "cpu", cpu_ms);
  state.counters["refined_share"] =
      static_cast<double>(std::count_if(refinements.begin(), refinements.end(), [](double r) { return r > 0; })) /
      static_cast<double>(std::max<size_t>(1, refinements.size()));
}
BENCHMARK(BM_ToppPublicMoves)->Unit(benchmark::kMillisecond)->Iterations(3);

// Analytic paths: straight C-space lines of public-move size, an arc, an S-curve.
std::vector<std::shared_ptr<const GeometricPath>> analyticPaths() {
  return {
      std::make_shared<testing::LinePath>(JointVector{{0.2, 1.57}}, JointVector{{1.97, 5.17}}),   // STOW -> L4
      std::make_shared<testing::LinePath>(JointVector{{1.97, 5.17}}, JointVector{{0.16, 0.10}}),  // L4 -> PROCESSOR
      std::make_shared<testing::LinePath>(JointVector{{0.5, 0.1}}, JointVector{{0.5, 6.0}}),      // arm only
      std::make_shared<testing::ArcPath>(JointVector{{1.0, 3.0}}, 0.8, 0.0, 3.0),
      std::make_shared<testing::WigglePath>(JointVector{{0.2, 1.0}}, JointVector{{1.5, 4.0}}, JointVector{{0.05, 0.8}},
                                            3.0, 2.0),
      std::make_shared<testing::LinePath>(JointVector{{0.5, 1.0}}, JointVector{{0.6, 1.2}}),  // short
  };
}

void BM_ToppAnalytic(benchmark::State& state) {
  const auto path = analyticPaths()[static_cast<size_t>(state.range(0))];
  ToppSolver solver;
  for (auto _ : state) {
    auto result = solver.solve(path, testing::referenceDrives());
    benchmark::DoNotOptimize(result);
    if (!result) state.SkipWithError(result.error().message.c_str());
  }
}
BENCHMARK(BM_ToppAnalytic)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);

void BM_Reachability(benchmark::State& state) {
  const auto path = analyticPaths()[static_cast<size_t>(state.range(0))];
  topp::Problem problem;
  topp::LimitMargins margins;
  topp::sampleGrid(*path, 200, problem);
  margins.reset(problem.intervals());
  (void)topp::buildRows(testing::referenceDrives(), margins, problem);
  problem.speed_bound = 1e3 / path->length();
  std::vector<double> b, c;
  for (auto _ : state) {
    auto r = topp::forwardBackward(problem, b, c);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_Reachability)->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);

// One evaluation of L_rho and its gradient: linear in K (the reported BigO).
void BM_AugmentedLagrangianEvaluation(benchmark::State& state) {
  const auto path = analyticPaths()[0];
  topp::Problem problem;
  topp::LimitMargins margins;
  topp::sampleGrid(*path, static_cast<int>(state.range(0)), problem);
  margins.reset(problem.intervals());
  (void)topp::buildRows(testing::referenceDrives(), margins, problem);
  problem.speed_bound = 1e3 / path->length();
  std::vector<double> b, c;
  topp::forwardBackward(problem, b, c);
  Eigen::VectorXd x, g;
  topp::initialGuess(problem, b, x);
  g.resize(x.size());
  topp::Multipliers m;
  topp::estimateMultipliers(problem, x, m);
  for (auto _ : state) benchmark::DoNotOptimize(topp::augmentedLagrangian(problem, m, 1e3, x, g));
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_AugmentedLagrangianEvaluation)->RangeMultiplier(2)->Range(50, 1600)->Complexity(benchmark::oN);

}  // namespace
}  // namespace cyber::planner

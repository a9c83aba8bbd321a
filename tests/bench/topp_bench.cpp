// Time-optimal parameterisation speed: median per move of the full ToppSolver::solve (grid,
// reachability warm start, augmented Lagrangian, 1 ms limit check and refinements).

#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "cyber/planner/topp.hpp"
#include "cyber/planner/topp_reachability.hpp"
#include "../unit/planner/topp_fixtures.hpp"

namespace cyber::planner {
namespace {

using testing::ArcPath;
using testing::LinePath;
using testing::WigglePath;

std::vector<std::shared_ptr<const GeometricPath>> paths() {
  return {
      std::make_shared<LinePath>(JointVector(0.2, 1.57), JointVector(1.97, 5.17)),   // STOW -> L4
      std::make_shared<LinePath>(JointVector(1.97, 5.17), JointVector(0.16, 0.10)),  // L4 -> PROCESSOR
      std::make_shared<LinePath>(JointVector(0.5, 0.1), JointVector(0.5, 6.0)),      // arm only
      std::make_shared<ArcPath>(JointVector(1.0, 3.0), 0.8, 0.0, 3.0),
      std::make_shared<WigglePath>(JointVector(0.2, 1.0), JointVector(1.5, 4.0), JointVector(0.05, 0.8), 3.0, 2.0),
      std::make_shared<LinePath>(JointVector(0.5, 1.0), JointVector(0.6, 1.2)),      // short
  };
}

void BM_ToppSolve(benchmark::State& state) {
  const auto path = paths()[static_cast<size_t>(state.range(0))];
  ToppSolver solver;
  for (auto _ : state) {
    auto result = solver.solve(path, testing::elevatorDrive(), testing::armDrive());
    benchmark::DoNotOptimize(result);
    if (!result) state.SkipWithError(result.error().reason.c_str());
  }
}
BENCHMARK(BM_ToppSolve)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);

void BM_Reachability(benchmark::State& state) {
  const auto path = paths()[static_cast<size_t>(state.range(0))];
  topp::Problem problem;
  topp::LimitMargins margins;
  topp::sampleGrid(*path, 200, problem);
  margins.reset(problem.intervals());
  const std::array<DriveParams, 2> drives{testing::elevatorDrive(), testing::armDrive()};
  topp::buildRows(drives, margins, problem, nullptr);
  std::vector<double> b, c;
  for (auto _ : state) {
    auto r = topp::forwardBackward(problem, b, c);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_Reachability)->DenseRange(0, 5)->Unit(benchmark::kMicrosecond);

void BM_AugmentedLagrangianEvaluation(benchmark::State& state) {
  const auto path = paths()[0];
  topp::Problem problem;
  topp::LimitMargins margins;
  topp::sampleGrid(*path, static_cast<int>(state.range(0)), problem);
  margins.reset(problem.intervals());
  const std::array<DriveParams, 2> drives{testing::elevatorDrive(), testing::armDrive()};
  topp::buildRows(drives, margins, problem, nullptr);
  std::vector<double> b, c;
  topp::forwardBackward(problem, b, c);
  Eigen::VectorXd x, g;
  topp::initialGuess(problem, b, x);
  g.resize(x.size());
  topp::Multipliers m;
  m.reset(problem);
  for (auto _ : state) benchmark::DoNotOptimize(topp::augmentedLagrangian(problem, m, 100.0, x, g));
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_AugmentedLagrangianEvaluation)->RangeMultiplier(2)->Range(50, 1600)->Complexity(benchmark::oN);

}  // namespace
}  // namespace cyber::planner

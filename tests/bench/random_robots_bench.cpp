// Whole-plan speed on the random robots (tests/support/random_robot.hpp) that RandomRobots
// judges: each robot's 20 seeded moves (the same draw, a quarter moving starts), planned
// `kRepetitions` times; median / p90 / p99 / max of MotionPlanner::plan's total and of the
// thread's CPU time per robot, and over every robot's plans (BM_RandomRobotMoves/all), with
// MotionPlanner::create (`create_ms`). docs/performance.md, "Seeded random moves".

#include <benchmark/benchmark.h>

#include <chrono>
#include <string>
#include <vector>

#include "bench_measures.hpp"
#include "cyber/planner/motion_planner.hpp"
#include "random_moves.hpp"
#include "random_robot.hpp"

namespace cyber::planner {
namespace {

constexpr int kRepetitions = 3;
constexpr int kRobots = 30;
constexpr unsigned kFirstSeed = 1;  // as RandomRobots

struct Measured {
  std::vector<double> total_ms, cpu_ms;
  int planned = 0, refused = 0;
};

// Plans one robot's moves kRepetitions times into `into`; the time MotionPlanner::create took, or
// a negative number when it failed.
double planRobot(unsigned seed, Measured& into) {
  const test::RandomRobot robot = test::randomRobot(seed);
  const auto t0 = std::chrono::steady_clock::now();
  const auto planner = MotionPlanner::create(robot.config.robot);
  const double create_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (!planner) return -1.0;
  std::vector<PlanRequest> requests;
  test::RandomMoveDraw draw(robot, planner.value(), robot.seed);
  for (int move = 0; move < test::kRandomMovesPerRobot; ++move) {
    if (const auto request = draw.next(move)) requests.push_back(*request);
  }
  for (int r = 0; r < kRepetitions; ++r) {
    for (const PlanRequest& request : requests) {
      const double cpu0 = bench::threadCpuMs();
      const auto plan = planner.value().plan(request);
      into.cpu_ms.push_back(bench::threadCpuMs() - cpu0);
      (plan ? into.planned : into.refused) += r == 0 ? 1 : 0;
      if (plan) into.total_ms.push_back(plan.value().times_ms.total);
    }
  }
  return create_ms;
}

void report(benchmark::State& state, const Measured& m) {
  bench::reportMs(state, "total", m.total_ms);
  bench::reportMs(state, "cpu", m.cpu_ms);
  state.counters["planned_moves"] = m.planned;
  state.counters["refused_moves"] = m.refused;
}

// Every robot's plans so far, for BM_RandomRobotMoves/all (registered last, so run last).
Measured& allRobots() {
  static Measured all;
  return all;
}

void BM_RandomRobotMoves(benchmark::State& state, unsigned seed) {
  Measured m;
  double create_ms = 0.0;
  for (auto _ : state) create_ms = planRobot(seed, m);
  if (create_ms < 0.0) {
    state.SkipWithError("MotionPlanner::create failed");
    return;
  }
  report(state, m);
  state.counters["create_ms"] = create_ms;
  state.counters["joints"] = test::randomJointCount(seed);
  Measured& all = allRobots();
  all.total_ms.insert(all.total_ms.end(), m.total_ms.begin(), m.total_ms.end());
  all.cpu_ms.insert(all.cpu_ms.end(), m.cpu_ms.begin(), m.cpu_ms.end());
  all.planned += m.planned;
  all.refused += m.refused;
}

// The robots' plans together; planned here when the per-robot runs were filtered out.
void BM_AllRandomRobotMoves(benchmark::State& state) {
  for (auto _ : state) {
    if (!allRobots().cpu_ms.empty()) continue;
    for (int i = 0; i < kRobots; ++i) planRobot(kFirstSeed + static_cast<unsigned>(i), allRobots());
  }
  report(state, allRobots());
}

const bool kRegistered = [] {
  for (int i = 0; i < kRobots; ++i) {
    const unsigned seed = kFirstSeed + static_cast<unsigned>(i);
    benchmark::RegisterBenchmark(("BM_RandomRobotMoves/seed_" + std::to_string(seed)).c_str(), BM_RandomRobotMoves,
                                 seed)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  }
  benchmark::RegisterBenchmark("BM_RandomRobotMoves/all", BM_AllRandomRobotMoves)
      ->Unit(benchmark::kMillisecond)
      ->Iterations(1);
  return true;
}();

}  // namespace
}  // namespace cyber::planner

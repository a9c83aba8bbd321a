#pragma once
// What the test of each path strategy shares (path_strategies.hpp): the reference robot's planner
// with every gate shut, the candidates of one public move with some strategies, and the two
// properties each strategy's test states on its own moves: on a public move it was made for it adds
// its candidate, clear of the obstacles and, where it puts it first, faster than the first path;
// where its gate is shut or it does not apply, it adds nothing.

#include <gtest/gtest.h>

#include <algorithm>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "path/strategies/path_strategies.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"
#include "timing/path_timing.hpp"

namespace cyber::planner::test_strategies {

inline const PathStrategy& strategyNamed(std::string_view name) {
  for (const PathStrategy& s : pathStrategies()) {
    if (s.name == name) return s;
  }
  ADD_FAILURE() << "no strategy " << name;
  return pathStrategies().front();
}

// The reference robot with every ratio gate shut: no strategy's estimate can pass it.
inline const PathPlanner& gatesShutPlanner() {
  static const PathPlanner p = [] {
    RobotModel m = test::referenceModel();
    PathStrategySettings& s = m.planner.strategies;
    s.direct_shape_ratio = s.detour_ratio = s.shape_ratio = s.synchronised_ratio = 1e9;
    s.synchronised_max_ratio = 2e9;
    return PathPlanner(m, m.scenes.front());
  }();
  return p;
}

inline std::vector<PlannedPath> candidatesOf(const PathPlanner& planner, const std::string& move,
                                             std::span<const PathStrategy> strategies,
                                             const JointVector& start_velocity = JointVector::Zero(2)) {
  const test::PublicMove& m = test::publicMove(move);
  auto found = planner.candidates(m.from, m.to, m.pieces, start_velocity, strategies);
  EXPECT_TRUE(found.ok()) << move << ": " << (found.ok() ? "" : found.error().message);
  return found.ok() ? std::move(found).value() : std::vector<PlannedPath>{};
}

struct MadeFor {
  const char* strategy;
  const char* move;                 // a public move of the reference robot
  PlanMethod::Smoothing smoothing;  // how its candidate becomes a spline
  bool put_first;                   // it replaces the fastest only when faster (else: in the order of its estimate)
};

inline void PrintTo(const MadeFor& c, std::ostream* os) { *os << c.strategy << " on " << c.move; }

class StrategyMadeFor : public ::testing::TestWithParam<MadeFor> {};

TEST_P(StrategyMadeFor, AddsAClearCandidateOnItsMove) {
  const MadeFor& c = GetParam();
  const PathPlanner& planner = test::referencePathPlanner();
  const PathStrategy& strategy = strategyNamed(c.strategy);
  const std::vector<PlannedPath> first = candidatesOf(planner, c.move, {});
  const std::vector<PlannedPath> with = candidatesOf(planner, c.move, {&strategy, 1});
  ASSERT_EQ(first.size(), 1u);
  ASSERT_GT(with.size(), first.size());
  const auto added = std::find_if(with.begin(), with.end(), [&](const auto& p) {
    return p.method.strategy == c.strategy && p.method.smoothing == c.smoothing;
  });
  ASSERT_NE(added, with.end()) << c.move << ": first " << with.front().method.name();
  EXPECT_GE(added->min_clearance_m, planner.model().clearance_m);
  EXPECT_TRUE(added->waypoints.front().isApprox(test::publicMove(c.move).from));
  EXPECT_TRUE(added->waypoints.back().isApprox(test::publicMove(c.move).to));
  const DriveModel drives = planner.model().driveModel(first.front().pieces);
  const PathStrategySettings& s = planner.model().planner.strategies;
  if (c.put_first) {
    EXPECT_EQ(added, with.begin());
    EXPECT_LT(estimateDuration(*added->path, drives, 0.0, s.check_grid_points),
              (1.0 - s.shape_gain) * estimateDuration(*first.front().path, drives, 0.0, s.check_grid_points));
  } else {
    for (size_t i = 1; i < with.size(); ++i) {
      EXPECT_LE(estimateDuration(*with[i - 1].path, drives, 0.0, s.timing_grid_points),
                estimateDuration(*with[i].path, drives, 0.0, s.timing_grid_points))
          << i;
    }
  }
}

struct AddsNothing {
  const char* name;
  const char* strategy;
  const char* move;
  bool gates_shut;  // on gatesShutPlanner()
  JointVector start_velocity;
};

inline void PrintTo(const AddsNothing& c, std::ostream* os) { *os << c.name; }

class StrategyAddsNothing : public ::testing::TestWithParam<AddsNothing> {};

TEST_P(StrategyAddsNothing, WhenItsGateIsShutOrItDoesNotApply) {
  const AddsNothing& c = GetParam();
  const PathPlanner& planner = c.gates_shut ? gatesShutPlanner() : test::referencePathPlanner();
  const PathStrategy& strategy = strategyNamed(c.strategy);
  const std::vector<PlannedPath> first = candidatesOf(planner, c.move, {}, c.start_velocity);
  const std::vector<PlannedPath> with = candidatesOf(planner, c.move, {&strategy, 1}, c.start_velocity);
  ASSERT_EQ(with.size(), first.size());
  EXPECT_EQ(with.front().method, first.front().method) << with.front().method.name();
}

}  // namespace cyber::planner::test_strategies

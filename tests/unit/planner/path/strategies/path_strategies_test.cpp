// Each path strategy on its own (path_strategies.hpp): on a public move of the reference robot it
// was made for it adds its candidate, clear of the obstacles and, where it puts it first, faster
// than the first path; where its gate is shut or it does not apply, it adds nothing. The list
// itself: its order, and every entry named with its reason.

#include "path/strategies/path_strategies.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "timing/path_timing.hpp"

#include "public_moves.hpp"
#include "reference_model.hpp"

namespace cyber::planner {
namespace {

const PathStrategy& strategyNamed(std::string_view name) {
  for (const PathStrategy& s : pathStrategies()) {
    if (s.name == name) return s;
  }
  ADD_FAILURE() << "no strategy " << name;
  return pathStrategies().front();
}

// The reference robot with every ratio gate shut: no strategy's estimate can pass it.
const PathPlanner& gatesShutPlanner() {
  static const PathPlanner p = [] {
    RobotModel m = test::referenceModel();
    PathStrategySettings& s = m.planner.strategies;
    s.direct_shape_ratio = s.detour_ratio = s.shape_ratio = s.synchronised_ratio = 1e9;
    s.synchronised_max_ratio = 2e9;
    return PathPlanner(m, m.scenes.front());
  }();
  return p;
}

std::vector<PlannedPath> candidatesOf(const PathPlanner& planner, const std::string& move,
                                      std::span<const PathStrategy> strategies,
                                      const JointVector& start_velocity = JointVector::Zero()) {
  const test::PublicMove& m = test::publicMove(move);
  auto found = planner.candidates(m.from, m.to, m.pieces, start_velocity, strategies);
  EXPECT_TRUE(found.ok()) << move << ": " << (found.ok() ? "" : found.error().message);
  return found.ok() ? std::move(found).value() : std::vector<PlannedPath>{};
}

bool startsWith(const std::string& text, std::string_view prefix) { return text.rfind(prefix, 0) == 0; }

TEST(PathStrategies, AreTriedInTheirDocumentedOrderEachWithItsReason) {
  std::vector<std::string_view> names;
  std::set<std::string_view> unique;
  for (const PathStrategy& s : pathStrategies()) {
    names.push_back(s.name);
    unique.insert(s.name);
    EXPECT_GT(s.reason.size(), 20u) << s.name;
    EXPECT_NE(s.run, nullptr) << s.name;
  }
  EXPECT_EQ(unique.size(), names.size());
  // Shortcuts and other ways come before the shape search, which starts from the fastest of them;
  // the synchronised candidate is judged against the fastest of all.
  const std::vector<std::string_view> expected{"shape the straight segment", "shortcut", "other ways round",
                                               "shape the fastest path", "synchronise the joints"};
  EXPECT_EQ(names, expected);
}

struct MadeFor {
  const char* strategy;
  const char* move;    // a public move of the reference robot
  const char* method;  // the prefix of the candidate's method
  bool put_first;      // it replaces the fastest only when faster (else: in the order of its estimate)
};

void PrintTo(const MadeFor& c, std::ostream* os) { *os << c.strategy << " on " << c.move; }

class StrategyMadeFor : public ::testing::TestWithParam<MadeFor> {};

TEST_P(StrategyMadeFor, AddsAClearCandidateOnItsMove) {
  const MadeFor& c = GetParam();
  const PathPlanner& planner = test::referencePathPlanner();
  const PathStrategy& strategy = strategyNamed(c.strategy);
  const std::vector<PlannedPath> first = candidatesOf(planner, c.move, {});
  const std::vector<PlannedPath> with = candidatesOf(planner, c.move, {&strategy, 1});
  ASSERT_EQ(first.size(), 1u);
  ASSERT_GT(with.size(), first.size());
  const auto added =
      std::find_if(with.begin(), with.end(), [&](const auto& p) { return startsWith(p.method, c.method); });
  ASSERT_NE(added, with.end()) << c.move << ": first " << with.front().method;
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

// On each, the reference robot's fastest plan comes from this strategy, which also beats the first
// path alone (docs/performance.md).
const MadeFor kMadeFor[] = {
    {"shape the straight segment", "none:STOW->INTAKE", "shaped for time, straight", true},
    {"shortcut", "none:INTAKE->L4", "shortcut, ", false},
    {"other ways round", "none:L1->NET", "other side, ", false},
    {"shape the fastest path", "none:STOW->L4", "shaped for time, ", true},
    {"synchronise the joints", "none:INTAKE->STOW", "synchronised joints", true},
    {"synchronise the joints", "coral:INTAKE->STOW", "synchronised joints", true},
};
INSTANTIATE_TEST_SUITE_P(Reference, StrategyMadeFor, ::testing::ValuesIn(kMadeFor));

struct AddsNothing {
  const char* name;
  const char* strategy;
  const char* move;
  bool gates_shut;  // on gatesShutPlanner()
  JointVector start_velocity;
};

void PrintTo(const AddsNothing& c, std::ostream* os) { *os << c.name; }

class StrategyAddsNothing : public ::testing::TestWithParam<AddsNothing> {};

TEST_P(StrategyAddsNothing, WhenItsGateIsShutOrItDoesNotApply) {
  const AddsNothing& c = GetParam();
  const PathPlanner& planner = c.gates_shut ? gatesShutPlanner() : test::referencePathPlanner();
  const PathStrategy& strategy = strategyNamed(c.strategy);
  const std::vector<PlannedPath> first = candidatesOf(planner, c.move, {}, c.start_velocity);
  const std::vector<PlannedPath> with = candidatesOf(planner, c.move, {&strategy, 1}, c.start_velocity);
  ASSERT_EQ(with.size(), first.size());
  EXPECT_EQ(with.front().method, first.front().method);
}

const AddsNothing kAddsNothing[] = {
    {"StraightSegmentAboveItsRatio", "shape the straight segment", "none:STOW->INTAKE", true, JointVector::Zero()},
    {"StraightSegmentOnASearchedPath", "shape the straight segment", "none:INTAKE->L4", false, JointVector::Zero()},
    {"ShortcutOfADirectPath", "shortcut", "none:STOW->INTAKE", false, JointVector::Zero()},
    {"OtherWaysBelowTheDetourRatio", "other ways round", "none:L1->NET", true, JointVector::Zero()},
    {"OtherWaysOfADirectPath", "other ways round", "none:STOW->INTAKE", false, JointVector::Zero()},
    {"ShapeBelowItsRatio", "shape the fastest path", "none:STOW->L4", true, JointVector::Zero()},
    {"SynchroniseOutsideItsWindow", "synchronise the joints", "none:INTAKE->STOW", true, JointVector::Zero()},
    {"SynchroniseFromAMovingStart", "synchronise the joints", "none:INTAKE->STOW", false, JointVector(0.2, 0.0)},
};
INSTANTIATE_TEST_SUITE_P(Reference, StrategyAddsNothing, ::testing::ValuesIn(kAddsNothing),
                         [](const ::testing::TestParamInfo<AddsNothing>& info) {
                           return std::string(info.param.name);
                         });

// With every strategy, candidates() is the first path and what the list adds, fastest first.
TEST(PathStrategies, TheWholeListIsWhatCandidatesTries) {
  const PathPlanner& planner = test::referencePathPlanner();
  for (const char* move : {"none:STOW->L4", "none:L1->NET", "coral:STOW->L2"}) {
    const test::PublicMove& m = test::publicMove(move);
    const auto all = planner.candidates(m.from, m.to, m.pieces);
    const auto listed = planner.candidates(m.from, m.to, m.pieces, JointVector::Zero(), pathStrategies());
    ASSERT_TRUE(all.ok() && listed.ok()) << move;
    ASSERT_EQ(all.value().size(), listed.value().size()) << move;
    for (size_t i = 0; i < all.value().size(); ++i) EXPECT_EQ(all.value()[i].method, listed.value()[i].method);
  }
}

}  // namespace
}  // namespace cyber::planner

// Adding a path strategy is one file and its test: a strategy registered from outside the
// strategies' folder (as the build lists a new file of it, planner/CMakeLists.txt) is listed by
// pathStrategies() in the order it names, is tried by candidates(), and is what the planner
// selects when its candidate comes first.
#include <gtest/gtest.h>

#include <string>

#include "cyber/planner.hpp"
#include "path/strategies/path_strategies.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"

namespace cyber::planner {
namespace {

constexpr const char* kThrowAway = "throw-away";

// A copy of the fastest candidate put first: the list marks it as this strategy's.
void markTheFastest(const CandidateInputs& /*in*/, CandidateList& list) {
  if (!list.empty()) list.putFirst(list.front());
}

const PathStrategyRegistration kRegistration{
    PathStrategy{.name = kThrowAway,
                 .reason = "a test's strategy: registering one is all it takes to have it tried",
                 .order = 1000,
                 .run = markTheFastest}};

TEST(RegisteringAStrategy, ListsItAfterTheBuiltInOnesInItsOrder) {
  const auto all = pathStrategies();
  ASSERT_EQ(all.size(), builtInPathStrategies().size() + 1);
  EXPECT_EQ(all.back().name, kThrowAway);
  EXPECT_EQ(all.back().run, &markTheFastest);
}

TEST(RegisteringAStrategy, TheChooserTriesItAndCanSelectIt) {
  const test::PublicMove& move = test::publicMove("none:STOW->L4");
  const auto candidates = test::referencePathPlanner().candidates(move.from, move.to, move.pieces);
  ASSERT_TRUE(candidates.ok()) << candidates.error().message;
  EXPECT_EQ(candidates.value().front().method.strategy, kThrowAway);

  auto planner = MotionPlanner::create(test::referenceModel(), GridSelection{0, 0.0});  // the grids it needs
  ASSERT_TRUE(planner.ok()) << planner.error().message;
  PlanRequest request;
  request.start = move.from;
  request.goal = move.to;
  request.pieces = move.pieces;
  const auto plan = planner.value().plan(request);
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  EXPECT_EQ(plan.value().method.strategy, kThrowAway) << plan.value().method.name();
}

}  // namespace
}  // namespace cyber::planner

// No change may make a public move slower unnoticed: every public move the reference robot can
// make is planned at rest and its duration must stay at or below the stored per-move ceiling
// (public_move_durations.hpp: the planner's own duration when the table was made, +0.1 %, beside
// the best known of docs/performance.md). Moves the table marks unreachable must stay refused.

#include <gtest/gtest.h>

#include "cyber/planner/motion_planner.hpp"
#include "public_move_durations.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"

namespace cyber::planner {
namespace {

TEST(PublicMoveDurations, EveryMoveIsAtMostItsStoredDuration) {
  const auto planner = MotionPlanner::create(test::referenceModel());
  ASSERT_TRUE(planner.ok());
  int checked = 0;
  for (const test::PublicMove& move : test::publicMoves()) {
    const test::StoredDuration* stored = test::storedDuration(move.label);
    ASSERT_NE(stored, nullptr) << move.label << " has no stored duration";
    SCOPED_TRACE(move.label);
    PlanRequest request;
    request.start = move.from;
    request.goal = move.to;
    request.pieces = move.pieces;
    const auto plan = planner.value().plan(request);
    if (stored->ceiling_s == 0.0) {
      EXPECT_FALSE(plan.ok()) << "a move stored as unreachable was planned";
      continue;
    }
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    EXPECT_LE(plan.value().trajectory->duration_s(), stored->ceiling_s);
    ++checked;
  }
  EXPECT_EQ(checked, 126);
}

}  // namespace
}  // namespace cyber::planner

// PlanStatus as a person and a shell see it: the text cyber-plan and the daemon print for every
// status, and the exit code of docs/design.md (0 planned, 2 bad input, 3 no feasible motion).

#include <iterator>
#include <set>
#include <string_view>

#include <gtest/gtest.h>

#include "cyber/planner/types.hpp"

namespace cyber::planner {
namespace {

// Every status, with the text and the exit code a caller may rely on.
struct Expected {
  PlanStatus status;
  std::string_view text;
  int exit_code;
};

constexpr Expected kEveryStatus[] = {
    {PlanStatus::kOk, "ok", 0},
    {PlanStatus::kInvalidInput, "invalid input", 2},
    {PlanStatus::kStartOutOfRange, "start out of range", 3},
    {PlanStatus::kGoalOutOfRange, "goal out of range", 3},
    {PlanStatus::kStartInCollision, "start in collision", 3},
    {PlanStatus::kGoalInCollision, "goal in collision", 3},
    {PlanStatus::kNoPath, "no path", 3},
    {PlanStatus::kClearanceNotMet, "clearance not met", 3},
    {PlanStatus::kInfeasibleStart, "infeasible start", 3},
    {PlanStatus::kSolverNotConverged, "solver did not converge", 3},
    {PlanStatus::kInternalError, "internal error", 3},
    {PlanStatus::kColumnsDisagree, "columns disagree", 3},
};

TEST(PlanStatusText, EveryStatusHasItsOwnText) {
  std::set<std::string_view> seen;
  for (const Expected& e : kEveryStatus) {
    EXPECT_EQ(toString(e.status), e.text) << static_cast<int>(e.status);
    EXPECT_TRUE(seen.insert(toString(e.status)).second) << "two statuses print " << toString(e.status);
  }
  // The table above covers the enum: the value after the last one is not a status.
  EXPECT_EQ(static_cast<int>(PlanStatus::kColumnsDisagree) + 1, static_cast<int>(std::size(kEveryStatus)));
}

TEST(PlanStatusText, AValueOutsideTheEnumIsUnknown) {
  EXPECT_EQ(toString(static_cast<PlanStatus>(static_cast<int>(PlanStatus::kColumnsDisagree) + 1)), "unknown");
  EXPECT_EQ(toString(static_cast<PlanStatus>(-1)), "unknown");
}

TEST(PlanStatusExitCode, PlannedIsZeroBadInputTwoAndNoFeasibleMotionThree) {
  for (const Expected& e : kEveryStatus) EXPECT_EQ(exitCodeOf(e.status), e.exit_code) << toString(e.status);
}

}  // namespace
}  // namespace cyber::planner

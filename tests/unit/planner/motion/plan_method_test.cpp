// A plan's method as a person reads it in a log (PlanMethod::name): the stop or the way out first,
// the strategy with its smoothing, the repairs last; and every repair is a bit of its own.
#include <gtest/gtest.h>

#include "cyber/planner.hpp"

namespace cyber::planner {
namespace {

TEST(PlanMethod, NamesTheStrategyItsSmoothingAndItsRepairsInOrder) {
  PlanMethod method;
  EXPECT_EQ(method.name(), "first path (optimised)");
  method.strategy = "shape the fastest path";
  method.smoothing = PlanMethod::Smoothing::kShaped;
  method.shaped_from = "shortcut";
  method.repairs = PlanMethod::kStoppedFirst | PlanMethod::kSlowedAfterStop;
  EXPECT_EQ(method.name(),
            "stop, then shape the fastest path (shaped for time from shortcut), slowed to agree after "
            "the stop");
  method = PlanMethod{};
  method.smoothing = PlanMethod::Smoothing::kStraight;
  method.repairs = PlanMethod::kLeftTheClearance | PlanMethod::kSlowedToAgree | PlanMethod::kGentlerStart;
  EXPECT_EQ(
      method.name(),
      "out of the clearance, then first path (straight), slowed to agree at 1 ms, gentler start to agree at 1 ms");
}

TEST(PlanMethod, EachRepairIsItsOwnBit) {
  const PlanMethod::Repair all[] = {PlanMethod::kStoppedFirst, PlanMethod::kLeftTheClearance,
                                    PlanMethod::kSlowedToAgree, PlanMethod::kGentlerStart,
                                    PlanMethod::kSlowedAfterStop};
  for (const PlanMethod::Repair repair : all) {
    PlanMethod method;
    method.repairs = repair;
    for (const PlanMethod::Repair other : all) EXPECT_EQ(method.has(other), other == repair);
  }
}

}  // namespace
}  // namespace cyber::planner

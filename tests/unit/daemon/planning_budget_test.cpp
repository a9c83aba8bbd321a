#include "cyber/daemon/planning_budget.hpp"

#include <gtest/gtest.h>

namespace cyber::daemon {
namespace {

TEST(PlanningBudget, NeverBelowTheConfiguredBudget) {
  PlanningBudget budget(0.03, 0.006, 1.0);
  EXPECT_DOUBLE_EQ(budget.budgetS(), 0.03);
  budget.record(0.001);
  EXPECT_DOUBLE_EQ(budget.budgetS(), 0.03);
}

TEST(PlanningBudget, FollowsTheSlowestRecentPlanWithHeadroomAndForgetsOldOnes) {
  PlanningBudget budget(0.03, 0.006, 1.0);
  budget.record(0.08);
  EXPECT_DOUBLE_EQ(budget.budgetS(), 1.25 * 0.08 + 0.006);
  for (std::size_t i = 0; i < PlanningBudget::kWindow - 1; ++i) budget.record(0.002);
  EXPECT_DOUBLE_EQ(budget.budgetS(), 1.25 * 0.08 + 0.006);  // still in the window
  budget.record(0.002);
  EXPECT_DOUBLE_EQ(budget.budgetS(), 0.03);  // pushed out
}

TEST(PlanningBudget, IsCapped) {
  PlanningBudget budget(0.03, 0.006, 0.5);
  budget.record(3.0);
  EXPECT_DOUBLE_EQ(budget.budgetS(), 0.5);
}

}  // namespace
}  // namespace cyber::daemon

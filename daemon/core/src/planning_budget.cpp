#include "cyber/daemon/planning_budget.hpp"

#include <algorithm>

namespace cyber::daemon {

PlanningBudget::PlanningBudget(double configured_s, double margin_s, double max_s)
    : configured_s_(configured_s), margin_s_(margin_s), max_s_(std::max(max_s, configured_s)) {}

void PlanningBudget::record(double plan_time_s) {
  recent_[next_] = plan_time_s;
  next_ = (next_ + 1) % kWindow;
  count_ = std::min(count_ + 1, kWindow);
}

double PlanningBudget::budgetS() const {
  double slowest = 0.0;
  for (std::size_t i = 0; i < count_; ++i) slowest = std::max(slowest, recent_[i]);
  return std::min(max_s_, std::max(configured_s_, kHeadroom * slowest + margin_s_));
}

}  // namespace cyber::daemon

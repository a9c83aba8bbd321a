#include "cyber/daemon/goal_status.hpp"

namespace cyber::daemon {

std::string_view toString(GoalStatus status) {
  switch (status) {
    case GoalStatus::kAccepted: return "accepted";
    case GoalStatus::kPlanning: return "planning";
    case GoalStatus::kExecuting: return "executing";
    case GoalStatus::kDone: return "done";
    case GoalStatus::kRejected: return "rejected";
    case GoalStatus::kFailed: return "failed";
    case GoalStatus::kCancelled: return "cancelled";
  }
  return "unknown";
}

GoalStatus statusOfPlanError(planner::PlanStatus status) {
  switch (status) {
    case planner::PlanStatus::kInvalidInput:
    case planner::PlanStatus::kGoalOutOfRange:
    case planner::PlanStatus::kGoalInCollision: return GoalStatus::kRejected;
    default: return GoalStatus::kFailed;
  }
}

}  // namespace cyber::daemon

#pragma once
// The life of a goal on ARM_PLAN_STATUS (same numbers as arm_plan_status_t's STATUS_*).

#include <cstdint>
#include <string>
#include <string_view>

#include "cyber/daemon/planning_service.hpp"
#include "cyber/planner.hpp"

namespace cyber::daemon {

enum class GoalStatus : std::int8_t {
  kAccepted = 0,
  kPlanning = 1,
  kExecuting = 2,
  kDone = 3,
  kRejected = 4,
  kFailed = 5,
  kCancelled = 6,
};

std::string_view toString(GoalStatus status);
[[nodiscard]] inline bool isFinal(GoalStatus status) {
  return status == GoalStatus::kDone || status == GoalStatus::kRejected || status == GoalStatus::kFailed ||
         status == GoalStatus::kCancelled;
}

// A planner error on a goal: the goal itself is bad (malformed, out of range, in collision) ->
// REJECTED; the planner could not find a motion from where the mechanism is -> FAILED.
GoalStatus statusOfPlanError(planner::PlanStatus status);

struct StatusUpdate {
  std::int64_t request_id = 0;
  GoalStatus status = GoalStatus::kAccepted;
  std::string reason;
  StageTimesMs times_ms;
  double duration_s = 0.0;
};

}  // namespace cyber::daemon

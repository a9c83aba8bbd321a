#include "cyber/planner/types.hpp"

namespace cyber::planner {

std::string_view toString(PlanStatus status) {
  switch (status) {
    case PlanStatus::kOk: return "ok";
    case PlanStatus::kInvalidInput: return "invalid input";
    case PlanStatus::kStartOutOfRange: return "start out of range";
    case PlanStatus::kGoalOutOfRange: return "goal out of range";
    case PlanStatus::kStartInCollision: return "start in collision";
    case PlanStatus::kGoalInCollision: return "goal in collision";
    case PlanStatus::kNoPath: return "no path";
    case PlanStatus::kClearanceNotMet: return "clearance not met";
    case PlanStatus::kInfeasibleStart: return "infeasible start";
    case PlanStatus::kSolverNotConverged: return "solver did not converge";
    case PlanStatus::kInternalError: return "internal error";
    case PlanStatus::kColumnsDisagree: return "columns disagree";
  }
  return "unknown";
}

int exitCodeOf(PlanStatus status) {
  switch (status) {
    case PlanStatus::kOk: return 0;
    case PlanStatus::kInvalidInput: return 2;
    default: return 3;
  }
}

}  // namespace cyber::planner

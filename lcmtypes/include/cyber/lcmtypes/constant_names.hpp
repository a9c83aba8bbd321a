#pragma once
// The names of the STATUS_* and MODE_* constants of the LCM types (docs/lcm.md), without the
// prefix: what logs and dashboards show instead of the numbers.

#include "cyberplanner/arm_plan_status_t.hpp"
#include "cyberplanner/arm_setpoint_t.hpp"

namespace cyber::lcmtypes {

inline const char* statusName(int status) {
  using S = cyberplanner::arm_plan_status_t;
  switch (status) {
    case S::STATUS_ACCEPTED: return "ACCEPTED";
    case S::STATUS_PLANNING: return "PLANNING";
    case S::STATUS_EXECUTING: return "EXECUTING";
    case S::STATUS_DONE: return "DONE";
    case S::STATUS_REJECTED: return "REJECTED";
    case S::STATUS_FAILED: return "FAILED";
    case S::STATUS_CANCELLED: return "CANCELLED";
    default: return "UNKNOWN";
  }
}

inline const char* modeName(int mode) {
  using M = cyberplanner::arm_setpoint_t;
  switch (mode) {
    case M::MODE_NO_STATE: return "NO_STATE";
    case M::MODE_HOLDING: return "HOLDING";
    case M::MODE_MOVING: return "MOVING";
    case M::MODE_FAULT: return "FAULT";
    case M::MODE_ROBOT_DISABLED: return "ROBOT_DISABLED";
    case M::MODE_RELEASED: return "RELEASED";
    default: return "UNKNOWN";
  }
}

}  // namespace cyber::lcmtypes

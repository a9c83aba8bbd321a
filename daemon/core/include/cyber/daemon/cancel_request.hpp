#pragma once
// A cancel as it arrives on ARM_CANCEL (arm_cancel_t; docs/lcm.md, "Cancel and manual override").

#include <cstdint>

namespace cyber::daemon {

// Same numbers as arm_cancel_t's ACTION_*.
enum class CancelAction : std::int8_t {
  kHold = 0,     // every open goal ends CANCELLED; brake to rest as fast as the limits allow and hold
  kRelease = 1,  // every open goal ends CANCELLED; stream no setpoints until the next goal (manual override)
};

struct CancelRequest {
  static constexpr std::int64_t kActive = -1;  // whatever goal is open

  std::int64_t request_id = kActive;  // the goal to stop
  CancelAction action = CancelAction::kHold;
};

}  // namespace cyber::daemon

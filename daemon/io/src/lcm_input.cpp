#include "cyber/daemon/io/lcm_input.hpp"

#include <fmt/ranges.h>

#include "cyber/daemon/io/lcm_messages.hpp"
#include "cyber/daemon/io/monotonic_clock.hpp"

namespace cyber::daemon::io {

LcmInput::LcmInput(const planner::RobotModel& robot, StreamerChannels& channels, GoalHandler on_goal,
                   CancelHandler on_cancel)
    : robot_(robot), channels_(channels), on_goal_(std::move(on_goal)), on_cancel_(std::move(on_cancel)) {}

LcmBridge::Callbacks LcmInput::callbacks() {
  return LcmBridge::Callbacks{[this](const cyberplanner::arm_goal_t& m) { on_goal_(goalFromMessage(m)); },
                              [this](const cyberplanner::arm_cancel_t& m) {
                                if (const auto cancel = cancelFromMessage(m)) {
                                  on_cancel_(*cancel);
                                  return;
                                }
                                ++undecodable_;
                                undecodable_warning_.warn(monotonicNow(),
                                                          "ignoring ARM_CANCEL for request {} with unknown action {}",
                                                          m.request_id, int{m.action});
                              },
                              [this](const std::string& channel, int size) {
                                ++undecodable_;
                                warnUndecodable(undecodable_warning_, channel, size);
                              }};
}

void LcmInput::onState(const cyberplanner::arm_state_t& message) {
  const MonoNs now = monotonicNow();
  const auto state = stateFromMessage(message, robot_);
  if (!state) {
    ++bad_states_;
    state_warning_.warn(now,
                        "ignoring ARM_STATE with {} joints (this robot has {}) or non-finite or out-of-range "
                        "positions [{}]",
                        int{message.num_joints}, robot_.joints.size(), fmt::join(message.position, ", "));
    return;
  }
  state_.state_ns = now;
  state_.joint_count = static_cast<int>(state->q.size());
  for (int j = 0; j < state->q.size(); ++j) {
    state_.measured_q[j] = state->q[j];
    state_.measured_qdot[j] = state->qdot[j];
  }
  channels_.state.store(state_);
}

void LcmInput::onUndecodableState(const std::string& channel, int size) {
  ++undecodable_;
  warnUndecodable(state_undecodable_warning_, channel, size);
}

void LcmInput::warnUndecodable(ThrottledWarning& warning, const std::string& channel, int size) {
  warning.warn(monotonicNow(), "undecodable message on {} ({} bytes: wrong type, fingerprint or corrupt)", channel,
               size);
}

}  // namespace cyber::daemon::io

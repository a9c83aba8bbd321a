#include "cyber/daemon/io/lcm_input.hpp"

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
    state_warning_.warn(now, "ignoring ARM_STATE with non-finite or out-of-range values ({} {} {}, {} {} {})",
                        robot_.joints[0].name, message.position[0], planner::unitName(robot_.joints[0].type),
                        robot_.joints[1].name, message.position[1], planner::unitName(robot_.joints[1].type));
    return;
  }
  state_.state_ns = now;
  state_.measured_q[0] = state->q[0];
  state_.measured_q[1] = state->q[1];
  state_.measured_qdot[0] = state->qdot[0];
  state_.measured_qdot[1] = state->qdot[1];
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

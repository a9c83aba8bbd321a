#include "cyber/daemon/io/lcm_bridge.hpp"

#include "cyber/lcmtypes/safe_decode.hpp"

namespace cyber::daemon::io {

LcmBridge::LcmBridge(lcm::LCM& lcm, const config::ChannelNames& channels, Callbacks callbacks)
    : lcm_(lcm), channels_(channels), callbacks_(std::move(callbacks)) {
  // LCM's receive thread queues at most 30 messages per subscription by default and drops the
  // rest without a word. Every goal must be answered, so goals may queue far more (a 1000/s flood
  // for 10 s); states are latest-wins, and old ones are worth nothing.
  lcm_.subscribe(channels_.goal, &LcmBridge::onGoal, this)->setQueueCapacity(kGoalQueueCapacity);
  lcm_.subscribe(channels_.state, &LcmBridge::onState, this);
}

int LcmBridge::handleReady(int max_messages) {
  int handled = 0;
  while (handled < max_messages && lcm_.handleTimeout(0) > 0) ++handled;
  return handled;
}

void LcmBridge::onGoal(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  cyberplanner::arm_goal_t message;
  if (lcmtypes::safeDecode(message, buffer->data, static_cast<int>(buffer->data_size)) < 0) {
    callbacks_.undecodable(channel, static_cast<int>(buffer->data_size));
    return;
  }
  callbacks_.goal(message);
}

void LcmBridge::onState(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  cyberplanner::arm_state_t message;
  if (lcmtypes::safeDecode(message, buffer->data, static_cast<int>(buffer->data_size)) < 0) {
    callbacks_.undecodable(channel, static_cast<int>(buffer->data_size));
    return;
  }
  callbacks_.state(message);
}

}  // namespace cyber::daemon::io

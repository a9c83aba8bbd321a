#include "cyber/daemon/io/lcm_bridge.hpp"

namespace cyber::daemon::io {

LcmBridge::LcmBridge(lcm::LCM& lcm, const config::ChannelNames& channels, Callbacks callbacks)
    : lcm_(lcm), channels_(channels), callbacks_(std::move(callbacks)) {
  // LCM's receive thread queues at most 30 messages per subscription by default and drops the
  // rest without a word. Every goal must be answered, so goals may queue far more (a 1000/s flood
  // for 10 s).
  lcm_.subscribe(channels_.goal, &LcmBridge::onGoal, this)->setQueueCapacity(kGoalQueueCapacity);
  // A lost cancel would leave a move running (or a manual override unserved): queued like goals.
  lcm_.subscribe(channels_.cancel, &LcmBridge::onCancel, this)->setQueueCapacity(kGoalQueueCapacity);
}

int LcmBridge::handleReady(int max_messages) {
  int handled = 0;
  while (handled < max_messages && lcm_.handleTimeout(0) > 0) ++handled;
  return handled;
}

void LcmBridge::onGoal(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  deliverDecoded<cyberplanner::arm_goal_t>(buffer, channel, callbacks_.goal, callbacks_.undecodable);
}

void LcmBridge::onCancel(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  deliverDecoded<cyberplanner::arm_cancel_t>(buffer, channel, callbacks_.cancel, callbacks_.undecodable);
}

}  // namespace cyber::daemon::io

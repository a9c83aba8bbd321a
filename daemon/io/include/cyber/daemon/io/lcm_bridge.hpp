#pragma once
// The daemon's LCM endpoint on the event-loop thread: raw subscriptions to the goal and state
// channels, decoded with safeDecode (an undecodable or foreign message is counted, never trusted),
// and typed publishing on the output channels.

#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <string>

#include "cyber/config/daemon_settings.hpp"
#include "cyberplanner/arm_goal_t.hpp"
#include "cyberplanner/arm_state_t.hpp"

namespace cyber::daemon::io {

class LcmBridge {
 public:
  struct Callbacks {
    std::function<void(const cyberplanner::arm_goal_t&)> goal;
    std::function<void(const cyberplanner::arm_state_t&)> state;
    std::function<void(const std::string& channel, int size)> undecodable;
  };

  static constexpr int kGoalQueueCapacity = 10000;

  LcmBridge(lcm::LCM& lcm, const config::ChannelNames& channels, Callbacks callbacks);
  LcmBridge(const LcmBridge&) = delete;
  LcmBridge& operator=(const LcmBridge&) = delete;

  [[nodiscard]] int fd() { return lcm_.getFileno(); }
  // Handles the messages already waiting, at most max_messages (so a flood cannot starve the
  // other descriptors of the loop). Returns how many were handled.
  int handleReady(int max_messages);

  // A failed send (e.g. ENOBUFS in a burst) is counted, not retried: the loop must not block.
  template <class Message>
  void publish(const std::string& channel, const Message& message) {
    if (lcm_.publish(channel, &message) != 0) ++publish_failures_;
  }
  [[nodiscard]] std::int64_t publishFailures() const { return publish_failures_; }
  [[nodiscard]] const config::ChannelNames& channels() const { return channels_; }

 private:
  void onGoal(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void onState(const lcm::ReceiveBuffer* buffer, const std::string& channel);

  lcm::LCM& lcm_;
  config::ChannelNames channels_;
  Callbacks callbacks_;
  std::int64_t publish_failures_ = 0;
};

}  // namespace cyber::daemon::io

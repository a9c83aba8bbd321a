#pragma once
// The daemon's LCM endpoint on the event-loop thread: raw subscriptions to the goal and cancel
// channels, decoded with safeDecode (an undecodable or foreign message is counted, never trusted), and typed
// publishing on the output channels. ARM_STATE has an LCM instance and a thread of its own
// (state_receiver.hpp).

#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <string>

#include "cyber/config/daemon_settings.hpp"
#include "cyber/lcmtypes/safe_decode.hpp"
#include "cyberplanner/arm_cancel_t.hpp"
#include "cyberplanner/arm_goal_t.hpp"

namespace cyber::daemon::io {

// Hands a received message to `on_message` decoded, or its channel and size to `on_undecodable`.
template <class Message, class OnMessage, class OnUndecodable>
void deliverDecoded(const lcm::ReceiveBuffer* buffer, const std::string& channel, OnMessage&& on_message,
                    OnUndecodable&& on_undecodable) {
  Message message{};
  if (lcmtypes::safeDecode(message, buffer->data, static_cast<int>(buffer->data_size)) < 0) {
    on_undecodable(channel, static_cast<int>(buffer->data_size));
    return;
  }
  on_message(message);
}

class LcmBridge {
 public:
  struct Callbacks {
    std::function<void(const cyberplanner::arm_goal_t&)> goal;
    std::function<void(const cyberplanner::arm_cancel_t&)> cancel;
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
  void onCancel(const lcm::ReceiveBuffer* buffer, const std::string& channel);

  lcm::LCM& lcm_;
  config::ChannelNames channels_;
  Callbacks callbacks_;
  std::int64_t publish_failures_ = 0;
};

}  // namespace cyber::daemon::io

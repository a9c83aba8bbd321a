#pragma once
// ARM_GOAL, ARM_CANCEL and ARM_STATE as the daemon receives them: goals and cancels (on the event
// loop) go on to `on_goal` and `on_cancel`, valid measured states (on the state receiver's thread, state_receiver.hpp)
// to the streamer (StreamerChannels::state); states with non-finite or absurd values, cancels with an unknown action
// and undecodable messages are counted (ARM_DAEMON_STATUS.decode_errors) and logged, throttled.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "cyber/daemon/cancel_request.hpp"
#include "cyber/daemon/goal_request.hpp"
#include "cyber/daemon/io/lcm_bridge.hpp"
#include "cyber/daemon/io/log_throttle.hpp"
#include "cyber/daemon/io/streamer_thread.hpp"
#include "cyber/planner.hpp"
#include "cyberplanner/arm_state_t.hpp"

namespace cyber::daemon::io {

class LcmInput {
 public:
  using GoalHandler = std::function<void(const GoalRequest&)>;
  using CancelHandler = std::function<void(const CancelRequest&)>;

  // `robot` and `channels` must outlive this.
  LcmInput(const planner::RobotModel& robot, StreamerChannels& channels, GoalHandler on_goal, CancelHandler on_cancel);
  LcmInput(const LcmInput&) = delete;
  LcmInput& operator=(const LcmInput&) = delete;

  // What the LcmBridge calls for each goal and cancel (event loop).
  [[nodiscard]] LcmBridge::Callbacks callbacks();
  // What the StateReceiver calls for each ARM_STATE (its thread only). A state is stamped here, on
  // CLOCK_MONOTONIC, as it is handed over.
  void onState(const cyberplanner::arm_state_t& message);
  void onUndecodableState(const std::string& channel, int size);

  // The latest valid ARM_STATE (state_ns kNever before the first). Any thread.
  [[nodiscard]] MeasuredStateData state() const { return channels_.state.load(); }
  // Undecodable or foreign messages on ARM_GOAL / ARM_CANCEL / ARM_STATE, decodable states with bad
  // values and cancels with an unknown action.
  [[nodiscard]] std::int64_t decodeErrors() const { return undecodable_.load() + bad_states_.load(); }

 private:
  static void warnUndecodable(ThrottledWarning& warning, const std::string& channel, int size);

  const planner::RobotModel& robot_;
  StreamerChannels& channels_;
  GoalHandler on_goal_;
  CancelHandler on_cancel_;
  MeasuredStateData state_;  // the receiver's copy
  std::atomic<std::int64_t> undecodable_{0};
  std::atomic<std::int64_t> bad_states_{0};
  ThrottledWarning undecodable_warning_;        // event loop
  ThrottledWarning state_undecodable_warning_;  // state receiver
  ThrottledWarning state_warning_;              // state receiver
};

}  // namespace cyber::daemon::io

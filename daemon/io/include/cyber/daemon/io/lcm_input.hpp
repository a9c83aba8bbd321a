#pragma once
// ARM_GOAL and ARM_STATE as the event loop receives them: goals go on to `on_goal`, valid measured
// states to the streamer (StreamerChannels::state); states with non-finite or absurd values and
// undecodable messages are counted (ARM_DAEMON_STATUS.decode_errors) and logged, throttled.

#include <cstdint>
#include <functional>
#include <string>

#include "cyber/daemon/goal_request.hpp"
#include "cyber/daemon/io/lcm_bridge.hpp"
#include "cyber/daemon/io/log_throttle.hpp"
#include "cyber/daemon/io/streamer_thread.hpp"
#include "cyber/planner/robot_model.hpp"

namespace cyber::daemon::io {

class LcmInput {
 public:
  using GoalHandler = std::function<void(const GoalRequest&)>;

  // `robot` and `channels` must outlive this.
  LcmInput(const planner::RobotModel& robot, StreamerChannels& channels, GoalHandler on_goal);
  LcmInput(const LcmInput&) = delete;
  LcmInput& operator=(const LcmInput&) = delete;

  // What the LcmBridge calls for each message.
  [[nodiscard]] LcmBridge::Callbacks callbacks();

  // The latest valid ARM_STATE (state_ns kNever before the first).
  [[nodiscard]] const MeasuredStateData& state() const { return state_; }
  // Undecodable or foreign messages on ARM_GOAL / ARM_STATE, and decodable states with bad values.
  [[nodiscard]] std::int64_t decodeErrors() const { return undecodable_ + bad_states_; }

 private:
  void onState(const cyberplanner::arm_state_t& message);
  void onUndecodable(const std::string& channel, int size);

  const planner::RobotModel& robot_;
  StreamerChannels& channels_;
  GoalHandler on_goal_;
  MeasuredStateData state_;
  std::int64_t undecodable_ = 0;
  std::int64_t bad_states_ = 0;
  ThrottledWarning undecodable_warning_;
  ThrottledWarning state_warning_;
};

}  // namespace cyber::daemon::io

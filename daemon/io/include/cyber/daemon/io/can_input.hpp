#pragma once
// The event loop's reading of its CAN socket, which receives only the controller's error frames
// (the streamer alone reads the robot frames, robot_link.hpp): each is counted and logged, and
// raises fault bit 0x10 for a second. An interface that is down keeps the socket readable with an
// error, so after a failed read the socket is left alone for 100 ms instead of spinning the loop.

#include <cstdint>

#include "cyber/can/can_socket.hpp"
#include "cyber/daemon/io/event_loop.hpp"
#include "cyber/daemon/io/log_throttle.hpp"
#include "cyber/daemon/mono_time.hpp"

namespace cyber::daemon::io {

class CanInput {
 public:
  CanInput(can::CanSocket& socket, EventLoop& loop);
  CanInput(const CanInput&) = delete;
  CanInput& operator=(const CanInput&) = delete;

  // Periodic: reads the socket again once a pause after a failed read is over.
  void onTimer(MonoNs now);

  // A controller error frame arrived less than `window` before now.
  [[nodiscard]] bool busErrorWithin(MonoNs now, MonoNs window) const {
    return bus_error_ns_ != kNever && now - bus_error_ns_ < window;
  }
  // Controller error frames and failed reads (ARM_DAEMON_STATUS.can_errors with the failed writes).
  [[nodiscard]] std::int64_t errors() const { return bus_errors_ + read_errors_; }

 private:
  void watch();
  void onReadable();

  can::CanSocket& socket_;
  EventLoop& loop_;
  std::int64_t bus_errors_ = 0;
  std::int64_t read_errors_ = 0;
  MonoNs bus_error_ns_ = kNever;
  MonoNs paused_until_ = kNever;
  ThrottledWarning warning_;
};

}  // namespace cyber::daemon::io

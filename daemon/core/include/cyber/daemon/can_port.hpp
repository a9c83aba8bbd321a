#pragma once
// Where setpoint and status frames go: the SocketCAN socket, a discarding port in simulation
// (--can none), or a recording fake in tests. write() must not block or allocate.

#include "cyber/can/can_socket.hpp"
#include "cyber/can/frame.hpp"

namespace cyber::daemon {

class CanPort {
 public:
  virtual ~CanPort() = default;
  virtual can::IoResult write(const can::Frame& frame) = 0;
};

// Simulation: every frame is accepted and dropped.
class DiscardingCanPort final : public CanPort {
 public:
  can::IoResult write(const can::Frame& /*frame*/) override { return {}; }
};

class SocketCanPort final : public CanPort {
 public:
  explicit SocketCanPort(can::CanSocket& socket) : socket_(socket) {}
  can::IoResult write(const can::Frame& frame) override { return socket_.write(frame); }

 private:
  can::CanSocket& socket_;
};

}  // namespace cyber::daemon

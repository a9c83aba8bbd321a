#pragma once
// Where setpoint and status frames go: the SocketCAN socket (daemon/io, can_socket_ports.hpp), a
// discarding port in simulation (--can none), or a recording fake in tests. write() must not
// block or allocate.

#include "cyber/can/frame.hpp"
#include "cyber/can/io_result.hpp"

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

}  // namespace cyber::daemon

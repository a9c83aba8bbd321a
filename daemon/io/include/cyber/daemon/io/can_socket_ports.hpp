#pragma once
// The daemon's CAN sockets behind the logic's frame ports (can_port.hpp, robot_link.hpp), and the
// socket options of each: the event loop's socket writes and reads error frames only; the
// streamer's receive-only socket reads the frames that gate motion (docs/design.md, "The motion
// gate").

#include <vector>

#include "cyber/can/can_socket.hpp"
#include "cyber/can/id_filter.hpp"
#include "cyber/daemon/can_port.hpp"
#include "cyber/daemon/robot_link.hpp"

namespace cyber::daemon::io {

class SocketCanPort final : public CanPort {
 public:
  explicit SocketCanPort(can::CanSocket& socket) : socket_(socket) {}
  can::IoResult write(const can::Frame& frame) override { return socket_.write(frame); }

 private:
  can::CanSocket& socket_;
};

class SocketRobotFrameSource final : public RobotFrameSource {
 public:
  explicit SocketRobotFrameSource(can::CanSocket& socket) : socket_(socket) {}
  can::IoResult read(can::Frame& frame) override { return socket_.read(frame); }

 private:
  can::CanSocket& socket_;
};

// What the streamer reads: the roboRIO heartbeat and the broadcast disable (id 0 in both formats).
std::vector<can::IdFilter> robotLinkFilters();

// The streamer's receive-only socket: robotLinkFilters(), no error frames.
can::SocketOptions robotLinkSocketOptions();

// The event loop's socket: no data frames (the streamer is the one reader of the robot frames),
// the controller's error frames.
can::SocketOptions eventLoopSocketOptions();

}  // namespace cyber::daemon::io

#pragma once
// The streamer's own reading of the frames that gate motion (roboRIO heartbeat, broadcast disable)
// from a receive-only CAN socket of its own, drained at every tick on its real-time thread. The
// event loop reads the same frames on its socket for counters and logs, but at normal priority:
// in a busy system it can fall behind by more than the 100 ms heartbeat timeout and the gate would
// stop motion on heartbeats that are on the bus (docs/design.md, "The motion gate").

#include <cstdint>

#include "cyber/can/can_socket.hpp"
#include "cyber/can/frame.hpp"
#include "cyber/daemon/mono_time.hpp"
#include "cyber/daemon/motion_gate.hpp"

namespace cyber::daemon {

// Where the streamer reads robot frames from; read() must not block or allocate.
class RobotFrameSource {
 public:
  virtual ~RobotFrameSource() = default;
  virtual can::IoResult read(can::Frame& frame) = 0;
};

class SocketRobotFrameSource final : public RobotFrameSource {
 public:
  explicit SocketRobotFrameSource(can::CanSocket& socket) : socket_(socket) {}
  can::IoResult read(can::Frame& frame) override { return socket_.read(frame); }

 private:
  can::CanSocket& socket_;
};

// The socket options of that receive-only socket: heartbeat and both id-0 forms, no error frames.
can::SocketOptions robotLinkSocketOptions();

struct RobotLink {
  MonoNs heartbeat_ns = kNever;     // when the streamer took in the latest valid heartbeat
  bool heartbeat_watchdog = false;  // its system-watchdog bit
  MonoNs broadcast_disable_ns = kNever;
  std::uint32_t broadcast_disable_count = 0;
};

// Reads at most max_frames frames (a flood cannot hold the tick) and records them at `now`, which
// is at most one period after their arrival. Heartbeats of the wrong length are skipped here (the
// event loop counts them). Returns the frames read; stops at the first error (nothing to read, or
// the interface down: the gate then sees the heartbeat age). Never allocates.
int drainRobotFrames(RobotFrameSource& source, MonoNs now, RobotLink& link, int max_frames = 32);

// The gate's inputs with the robot fields replaced by the streamer's own reading. Not the newer of
// the two: both stamp a frame with the time it was read, so a late reader makes a heartbeat look
// fresher than it is, and the event loop is the one that can be late (hil.daemon_faults once saw
// motion stop 130 ms after the last heartbeat with the newer-wins rule). The streamer reads at
// every tick, so its stamp is at most one period after the arrival.
void applyRobotLink(const RobotLink& link, RobotInputs& inputs);

}  // namespace cyber::daemon

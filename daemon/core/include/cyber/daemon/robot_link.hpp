#pragma once
// The daemon's only reading of the frames that gate motion (roboRIO heartbeat, broadcast disable):
// the streamer drains a receive-only CAN socket of its own at every tick on its real-time thread,
// and publishes what it read (StreamSnapshot) for goal admission, ARM_DAEMON_STATUS and the log.
// A reader at normal priority can fall behind by more than the 100 ms heartbeat timeout on a busy
// machine (docs/design.md, "The motion gate").

#include <cstdint>

#include "cyber/can/frame.hpp"
#include "cyber/can/io_result.hpp"
#include "cyber/can/robot_frames.hpp"
#include "cyber/daemon/mono_time.hpp"
#include "cyber/daemon/motion_gate.hpp"

namespace cyber::daemon {

// Where the streamer reads robot frames from: its receive-only CAN socket (daemon/io,
// can_socket_ports.hpp) or a fake in tests; read() must not block or allocate.
class RobotFrameSource {
 public:
  virtual ~RobotFrameSource() = default;
  virtual can::IoResult read(can::Frame& frame) = 0;
};

struct RobotLink {
  // How heartbeats are read: the config's [daemon] robot_controller (docs/can-protocol.md, "Robot
  // heartbeat"). Systemcore's reading is the default: on a roboRIO it can only close the gate more
  // often, never open it.
  can::HeartbeatLayout heartbeat_layout = can::HeartbeatLayout::kSystemcore;
  MonoNs heartbeat_ns = kNever;           // when the streamer took in the latest valid heartbeat
  bool heartbeat_watchdog = false;        // its system-watchdog bit
  bool heartbeat_motor_override = false;  // its FTC motor override flag (Systemcore only)
  MonoNs broadcast_disable_ns = kNever;
  std::uint32_t broadcast_disable_count = 0;
  std::int64_t bad_heartbeats = 0;  // heartbeat-id frames with a bad payload (ARM_DAEMON_STATUS.decode_errors)
};

// Reads at most max_frames frames (a flood cannot hold the tick) and records them at `now`, which
// is at most one period after their arrival. Heartbeats with a bad payload are counted and
// otherwise ignored. Returns the frames read; stops at the first error (nothing to read, or the
// interface down: the gate then sees the heartbeat age). Never allocates.
int drainRobotFrames(RobotFrameSource& source, MonoNs now, RobotLink& link, int max_frames = 32);

// The gate's inputs with the robot fields set from the streamer's reading: a frame is stamped
// with the tick that read it, at most one period after its arrival.
void applyRobotLink(const RobotLink& link, RobotInputs& inputs);

}  // namespace cyber::daemon

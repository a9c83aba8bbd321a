#pragma once
// Access to a Daemon's insides for tests and benchmarks only: its LCM instance (memq:// tests
// publish and subscribe through it, on the loop thread; ARM_STATE through its own), tasks run on the loop thread, the
// streamer's channels and the goal-to-first-setpoint latency.

#include "cyber/daemon/io/daemon.hpp"

namespace cyber::daemon::io {

class DaemonProbe {
 public:
  // Thread-safe: runs `task` on the loop thread.
  static void post(Daemon& daemon, EventLoop::Handler task) { daemon.loop_.post(std::move(task)); }
  // Loop thread only.
  static lcm::LCM& lcm(Daemon& daemon) { return *daemon.lcm_; }
  // The instance the daemon reads `channel` on: ARM_STATE has its own (state_receiver.hpp). For
  // publishing, from the loop thread.
  static lcm::LCM& lcmFor(Daemon& daemon, const std::string& channel) {
    return channel == daemon.options_.settings.channels.state ? *daemon.state_lcm_ : *daemon.lcm_;
  }
  static const StreamerChannels& channels(const Daemon& daemon) { return daemon.channels_; }
  static StreamerChannels& channels(Daemon& daemon) { return daemon.channels_; }
  // Loop thread, or after run() returned.
  static const LatencyHistogram& goalToSetpointLatency(const Daemon& daemon) { return daemon.goals_.goalLatency(); }
};

}  // namespace cyber::daemon::io

#pragma once
// ARM_TRAJECTORY, at most 10 messages a second: a flood of goals would otherwise put ~200 messages
// of up to 56 kB per second on the network. A plan adopted too soon after the last one published
// waits, and a newer plan replaces it (it supersedes it).

#include <cstdint>
#include <optional>

#include "cyber/daemon/io/lcm_bridge.hpp"
#include "cyber/daemon/mono_time.hpp"
#include "cyber/daemon/setpoint_source.hpp"

namespace cyber::daemon::io {

class TrajectoryPublisher {
 public:
  // Samples of the robot's `num_joints` joints `step_s` apart (docs/lcm.md). `bridge` must
  // outlive this.
  TrajectoryPublisher(LcmBridge& bridge, double step_s, int num_joints)
      : bridge_(bridge), step_s_(step_s), num_joints_(num_joints) {}

  // The trajectory the streamer adopted at start_ns: published now or, too soon after the last
  // one, by a later flush() unless a newer one replaces it.
  void offer(std::int64_t request_id, const SharedSetpointSource& trajectory, MonoNs start_ns, MonoNs now);
  // Publishes the waiting trajectory once the interval since the last one has passed.
  void flush(MonoNs now);

 private:
  struct Waiting {
    std::int64_t request_id = 0;
    SharedSetpointSource trajectory;
    MonoNs start_ns = 0;
  };

  LcmBridge& bridge_;
  double step_s_;
  int num_joints_;
  std::optional<Waiting> waiting_;
  MonoNs last_published_ns_ = kNever;
};

}  // namespace cyber::daemon::io

#include "cyber/daemon/io/trajectory_publisher.hpp"

#include "cyber/daemon/io/clock_pair.hpp"
#include "cyber/daemon/io/lcm_messages.hpp"

namespace cyber::daemon::io {

namespace {

constexpr MonoNs kInterval = 100'000'000;

}  // namespace

void TrajectoryPublisher::offer(std::int64_t request_id, const SharedSetpointSource& trajectory, MonoNs start_ns,
                                MonoNs now) {
  waiting_ = Waiting{request_id, trajectory, start_ns};
  flush(now);
}

void TrajectoryPublisher::flush(MonoNs now) {
  if (!waiting_) return;
  if (last_published_ns_ != kNever && now - last_published_ns_ < kInterval) return;
  last_published_ns_ = now;
  const ClockPair clocks = readClockPair();
  const Waiting waiting = std::move(*waiting_);
  waiting_.reset();
  bridge_.publish(bridge_.channels().trajectory,
                  trajectoryMessage(waiting.request_id, *waiting.trajectory, num_joints_,
                                    wallMicrosAt(waiting.start_ns, clocks), step_s_, clocks.wall_us));
}

}  // namespace cyber::daemon::io

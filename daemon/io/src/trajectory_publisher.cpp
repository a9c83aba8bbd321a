#include "cyber/daemon/io/trajectory_publisher.hpp"

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
  const std::int64_t wall = wallMicros();
  const Waiting waiting = std::move(*waiting_);
  waiting_.reset();
  bridge_.publish(bridge_.channels().trajectory,
                  trajectoryMessage(waiting.request_id, *waiting.trajectory,
                                    monoToWallMicros(waiting.start_ns, now, wall), step_s_, wall));
}

}  // namespace cyber::daemon::io

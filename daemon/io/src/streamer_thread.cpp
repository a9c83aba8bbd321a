#include "cyber/daemon/io/streamer_thread.hpp"

#include <cstdlib>
#include <optional>

#include <sys/prctl.h>

#include "cyber/daemon/io/monotonic_clock.hpp"
#include "cyber/daemon/io/thread_priority.hpp"
#include "cyber/notify/notifier.hpp"

namespace cyber::daemon::io {

RobotInputs gateInputs(const MeasuredStateData& state, const RobotLink& link, std::uint32_t release_generation) {
  RobotInputs inputs;
  inputs.release_generation = release_generation;
  inputs.state_ns = state.state_ns;
  inputs.measured_q = Eigen::Map<const JointVector>(state.measured_q, state.joint_count);
  inputs.measured_qdot = Eigen::Map<const JointVector>(state.measured_qdot, state.joint_count);
  applyRobotLink(link, inputs);
  return inputs;
}

StreamerThread::StreamerThread(StreamerChannels& channels, Streamer& streamer, FrameWriter& writer, MonoNs period_ns)
    : channels_(channels), streamer_(streamer), writer_(writer), period_ns_(period_ns) {}

StreamerThread::~StreamerThread() { stop(); }

void StreamerThread::start() {
  thread_ = std::thread([this] { run(); });
}

void StreamerThread::stop() {
  quit_.store(true);
  if (thread_.joinable()) thread_.join();
}

namespace {

constexpr double kMicrosecondsPerSecond = 1e6;  // the jitter histogram counts microseconds

}  // namespace

std::optional<MonoNs> StreamerThread::waitForPeriod(MonoNs& scheduled) {
  const std::uint64_t expirations = timer_.wait();
  if (expirations == 0) return std::nullopt;
  const MonoNs now = monotonicNow();
  scheduled += static_cast<MonoNs>(expirations - 1) * period_ns_;
  channels_.jitter.record(nsToSeconds(now - scheduled) * kMicrosecondsPerSecond);
  if (expirations > 1) {
    channels_.overruns.fetch_add(static_cast<std::int64_t>(expirations - 1), std::memory_order_relaxed);
    channels_.last_overrun_ns.store(now, std::memory_order_relaxed);
  }
  scheduled += period_ns_;
  return now;
}

void StreamerThread::publishSnapshot(MonoNs now, std::int64_t ticks, const TickOutput& out, const WriteReport& report) {
  StreamSnapshot snapshot;
  snapshot.ticks = ticks;
  snapshot.time_ns = now;
  snapshot.mode = out.mode;
  snapshot.gate_reason = out.gate_reason;
  snapshot.request_id = out.request_id;
  snapshot.segment_time_s = out.segment_time_s;
  snapshot.remaining_s = out.remaining_s;
  snapshot.robot_link = robot_link_;
  snapshot.setpoints_written = report.wire.written;
  snapshot.joints = report.wire.joints;
  channels_.snapshot.store(snapshot);
  channels_.frames_sent.store(writer_.framesSent(), std::memory_order_relaxed);
  channels_.write_failures.store(writer_.writeFailures(), std::memory_order_relaxed);
}

bool StreamerThread::handOver(MonoNs now, const TickOutput& out, const WriteReport& report) {
  bool wake = false;
  for (int i = 0; i < out.retired_count; ++i) {
    // Only a few programs exist at once (docs/design.md, "Threads and ownership"), so a full
    // ring is a defect; dropping the pointer would leak the program. abort() neither allocates
    // nor blocks.
    if (!channels_.retired.push(out.retired[static_cast<size_t>(i)])) std::abort();
    wake = true;
  }
  for (int i = 0; i < out.event_count; ++i) {
    if (!channels_.events.push(out.events[static_cast<size_t>(i)])) {
      channels_.lost_messages.fetch_add(1, std::memory_order_relaxed);
    }
    wake = true;
  }
  if (report.burst_started || report.burst_ended) {
    WriteNotice notice;
    notice.started = report.burst_started;
    notice.status = report.first_failure.status;
    notice.error_number = report.first_failure.error_number;
    notice.failures = report.burst_failures;
    notice.time_ns = now;
    if (!channels_.notices.push(notice)) channels_.lost_messages.fetch_add(1, std::memory_order_relaxed);
    wake = true;
  }
  return wake;
}

void StreamerThread::petWatchdog(MonoNs now, MonoNs& last_watchdog_ns) {
  const MonoNs watchdog_period = channels_.watchdog_period_ns.load(std::memory_order_relaxed);
  if (watchdog_period > 0 && (last_watchdog_ns == kNever || now - last_watchdog_ns >= watchdog_period) &&
      now - channels_.loop_alive_ns.load(std::memory_order_relaxed) <
          channels_.loop_alive_limit_ns.load(std::memory_order_relaxed)) {
    notify::notifyWatchdog();  // one non-blocking datagram, no allocation
    last_watchdog_ns = now;
  }
}

void StreamerThread::run() {
  // Real-time priority when allowed (root, CAP_SYS_NICE or RLIMIT_RTPRIO); plain scheduling otherwise.
  channels_.realtime_priority.store(requestRealtimePriority(kStreamerPriority));
  // Without this, a normal thread's timer wake-ups may be deferred by the default 50 us slack.
  prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);

  MonoNs scheduled = (monotonicNow() / period_ns_ + 1) * period_ns_;
  timer_.startPeriodic(scheduled, period_ns_);
  TickOutput out;
  std::int64_t ticks = 0;
  MonoNs last_watchdog_ns = kNever;
  while (!quit_.load(std::memory_order_relaxed)) {
    const std::optional<MonoNs> woke = waitForPeriod(scheduled);
    if (!woke) continue;
    const MonoNs now = *woke;

    if (robot_source_ != nullptr) drainRobotFrames(*robot_source_, now, robot_link_);
    // Never wait for the state: the receiver runs below this thread, so on one CPU a store this
    // tick interrupted cannot finish until the tick is over. The last state ages as it should.
    if (const std::optional<MeasuredStateData> state = channels_.state.tryLoad()) state_ = *state;
    const RobotInputs inputs =
        gateInputs(state_, robot_link_, channels_.release_generation.load(std::memory_order_relaxed));
    Program* offered = channels_.offered.exchange(nullptr, std::memory_order_acq_rel);
    streamer_.tick(now, inputs, offered, channels_.stop_requested.load(std::memory_order_relaxed), out);
    const WriteReport report = writer_.write(out, channels_.fault_bits.load(std::memory_order_relaxed));
    publishSnapshot(now, ++ticks, out, report);
    bool wake = handOver(now, out, report);
    petWatchdog(now, last_watchdog_ns);
    if (report.wire.written && channels_.wake_on_setpoints.load(std::memory_order_relaxed)) wake = true;
    if (wake) channels_.wake.signal();
  }
  if (Program* left = streamer_.releaseProgram()) channels_.retired.push(left);
}

}  // namespace cyber::daemon::io

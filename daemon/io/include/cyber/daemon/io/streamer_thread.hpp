#pragma once
// The setpoint streamer's thread: wakes on its own timerfd at the stream rate, ticks the Streamer,
// writes the frames and publishes what happened through lock-free structures. It never takes a
// lock, never logs, never touches LCM and never allocates; programs it is done with go back to the
// event loop to be freed there.

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <thread>

#include "cyber/daemon/frame_writer.hpp"
#include "cyber/daemon/io/fd.hpp"
#include "cyber/daemon/io/latency_histogram.hpp"
#include "cyber/daemon/io/latest_value.hpp"
#include "cyber/daemon/io/spsc_ring.hpp"
#include "cyber/daemon/robot_link.hpp"
#include "cyber/daemon/streamer.hpp"

namespace cyber::daemon::io {

// The measured state as plain data for the seqlock (Eigen vectors are not trivially copyable),
// stored by the event loop. The robot fields of RobotInputs are the streamer's (robot_link.hpp).
struct MeasuredStateData {
  MonoNs state_ns = kNever;
  int joint_count = 0;  // of the values below: the robot's, once a state has come
  double measured_q[planner::kMaxJoints] = {};
  double measured_qdot[planner::kMaxJoints] = {};
};

// The gate's inputs: the event loop's measured state, the streamer's reading of the robot link and
// the manual override (StreamerChannels::release_generation).
RobotInputs gateInputs(const MeasuredStateData& state, const RobotLink& link, std::uint32_t release_generation);

// The latest tick, for ARM_SETPOINT and ARM_DAEMON_STATUS.
struct StreamSnapshot {
  std::int64_t ticks = 0;
  MonoNs time_ns = 0;
  StreamMode mode = StreamMode::kNoState;
  GateReason gate_reason = GateReason::kNoState;
  std::int64_t request_id = -1;
  double segment_time_s = 0.0;
  double remaining_s = 0.0;
  RobotLink robot_link;  // the robot frames as the gate saw them at this tick
  bool setpoints_written = false;
  planner::PerJoint<can::Setpoint> joints;  // as written, by joint index
};

// CAN write bursts, for the log.
struct WriteNotice {
  bool started = false;  // false: ended
  can::IoStatus status = can::IoStatus::kOk;
  int error_number = 0;
  std::int64_t failures = 0;
  MonoNs time_ns = 0;
};

// Everything the event loop and the streamer thread share.
struct StreamerChannels {
  LatestValue<MeasuredStateData> state;
  std::atomic<Program*> offered{nullptr};
  std::atomic<bool> stop_requested{false};
  // ARM_CANCEL's release (RobotInputs::release_generation): odd while the robot program drives.
  std::atomic<std::uint32_t> release_generation{0};
  std::atomic<std::uint8_t> fault_bits{0};  // plan failed, bus error, overrun (set by the loop)

  SpscRing<StreamEvent, 1024> events;
  SpscRing<Program*, 64> retired;
  SpscRing<WriteNotice, 64> notices;
  LatestValue<StreamSnapshot> snapshot;
  EventFd wake;                                // the streamer has pushed events or notices
  std::atomic<bool> wake_on_setpoints{false};  // also after every tick that wrote setpoints

  std::atomic<std::int64_t> frames_sent{0};
  std::atomic<std::int64_t> write_failures{0};
  std::atomic<std::int64_t> overruns{0};
  std::atomic<std::int64_t> lost_messages{0};  // ring full (never expected; logged as an error)
  std::atomic<MonoNs> last_overrun_ns{kNever};
  LatencyHistogram jitter;
  std::atomic<int> realtime_priority{0};  // SCHED_FIFO priority obtained, 0 if refused (ARM_DAEMON_STATUS)

  // Service-manager watchdog: the streamer sends WATCHDOG=1 every watchdog_period_ns (0 = off),
  // but only while the event loop has shown life within loop_alive_limit_ns, so a stuck loop
  // is caught as well as a stuck streamer.
  std::atomic<MonoNs> watchdog_period_ns{0};
  std::atomic<MonoNs> loop_alive_ns{kNever};
  std::atomic<MonoNs> loop_alive_limit_ns{0};
};

class StreamerThread {
 public:
  StreamerThread(StreamerChannels& channels, Streamer& streamer, FrameWriter& writer, MonoNs period_ns);
  ~StreamerThread();
  StreamerThread(const StreamerThread&) = delete;
  StreamerThread& operator=(const StreamerThread&) = delete;

  // The streamer's source of heartbeats and disables (null: none, as without a CAN bus), and the
  // layout its heartbeats are read in (docs/can-protocol.md, "Robot heartbeat"). Set before start().
  void setRobotFrameSource(RobotFrameSource* source, can::HeartbeatLayout layout) {
    robot_source_ = source;
    robot_link_.heartbeat_layout = layout;
  }
  void start();
  // Ends after the current period and joins.
  void stop();

 private:
  void run();
  // The parts of one period, in order (each its own function so that run() reads as the period):
  // the timer's wake-up (none when it woke for nothing), the snapshot for the main thread, what the
  // main thread is handed (true when it should wake), and the watchdog's datagram.
  std::optional<MonoNs> waitForPeriod(MonoNs& scheduled);
  void publishSnapshot(MonoNs now, std::int64_t ticks, const TickOutput& out, const WriteReport& report);
  bool handOver(MonoNs now, const TickOutput& out, const WriteReport& report);
  void petWatchdog(MonoNs now, MonoNs& last_watchdog_ns);

  StreamerChannels& channels_;
  Streamer& streamer_;
  FrameWriter& writer_;
  MonoNs period_ns_;
  TimerFd timer_{true};
  std::atomic<bool> quit_{false};
  RobotFrameSource* robot_source_ = nullptr;
  RobotLink robot_link_;
  // The last ARM_STATE taken whole: kept when the receiver is in the middle of a store.
  MeasuredStateData state_;
  std::thread thread_;
};

}  // namespace cyber::daemon::io

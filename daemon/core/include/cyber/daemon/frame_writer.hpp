#pragma once
// Turns one streamer tick into CAN frames: a setpoint frame per joint (own sequence numbers) and,
// every few ticks, the daemon status frame. A frame that cannot be written is dropped, never
// queued: the next tick carries a fresher setpoint. Failures are counted and reported once per
// burst (the first failure, then the recovery with the burst's count) so the log is not flooded.

#include <array>
#include <cstdint>

#include "cyber/can/setpoint_codec.hpp"
#include "cyber/can/status_codec.hpp"
#include "cyber/daemon/can_port.hpp"
#include "cyber/daemon/streamer.hpp"

namespace cyber::daemon {

struct FrameWriterSettings {
  planner::PerJoint<std::uint8_t> joint_devices{1, 2};  // the setpoint frame of each joint, chain order
  std::uint8_t status_device = 3;
  int status_every_ticks = 20;  // 200 Hz / 10 Hz
};

// Setpoints as they went on the wire, decoded back (quantised), for ARM_SETPOINT.
struct WireSetpoints {
  bool written = false;                     // every joint's frame accepted by the port
  planner::PerJoint<can::Setpoint> joints;  // by joint index
};

struct WriteReport {
  int frames_written = 0;
  int frames_failed = 0;
  int encode_errors = 0;
  bool burst_started = false;       // first failure after a success
  bool burst_ended = false;         // first success after failures
  std::int64_t burst_failures = 0;  // with burst_ended: how many frames the burst lost
  can::IoResult first_failure;      // with burst_started
  bool status_sent = false;
  WireSetpoints wire;
};

class FrameWriter {
 public:
  FrameWriter(CanPort& port, const FrameWriterSettings& settings);

  // `fault_bits` are the status frame's fault bits the caller knows of (plan failed, bus error,
  // overrun); the writer adds "state stale" and "CAN write failed" itself.
  WriteReport write(const TickOutput& tick, std::uint8_t fault_bits);

  [[nodiscard]] std::int64_t framesSent() const { return frames_sent_; }
  [[nodiscard]] std::int64_t writeFailures() const { return write_failures_; }

 private:
  bool send(const can::Frame& frame, WriteReport& report);

  CanPort& port_;
  FrameWriterSettings settings_;
  std::array<std::uint8_t, planner::kMaxJoints> joint_sequences_{};
  std::uint8_t status_sequence_ = 0;
  int ticks_since_status_ = 0;
  bool failing_ = false;
  std::int64_t burst_failures_ = 0;
  std::int64_t frames_sent_ = 0;
  std::int64_t write_failures_ = 0;
};

}  // namespace cyber::daemon

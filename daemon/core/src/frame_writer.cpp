#include "cyber/daemon/frame_writer.hpp"

namespace cyber::daemon {

FrameWriter::FrameWriter(CanPort& port, const FrameWriterSettings& settings) : port_(port), settings_(settings) {}

bool FrameWriter::send(const can::Frame& frame, WriteReport& report) {
  const can::IoResult result = port_.write(frame);
  if (result.ok()) {
    ++frames_sent_;
    ++report.frames_written;
    if (failing_) {
      failing_ = false;
      report.burst_ended = true;
      report.burst_failures = burst_failures_;
      burst_failures_ = 0;
    }
    return true;
  }
  ++write_failures_;
  ++report.frames_failed;
  ++burst_failures_;
  if (!failing_) {
    failing_ = true;
    report.burst_started = true;
    report.first_failure = result;
  }
  return false;
}

WriteReport FrameWriter::write(const TickOutput& tick, std::uint8_t fault_bits) {
  WriteReport report;
  if (tick.send_setpoints) {
    planner::PerJoint<can::Frame> frames(settings_.joint_devices.size());
    bool encoded = true;
    for (int j = 0; j < frames.size(); ++j) {
      const can::Setpoint setpoint{tick.setpoints.position[j], tick.setpoints.velocity[j], tick.setpoints.volts[j],
                                   joint_sequences_[static_cast<size_t>(j)]++};
      auto frame = can::encodeSetpoint(settings_.joint_devices[j], setpoint);
      if (frame) {
        frames[j] = frame.value();
      } else {
        encoded = false;
      }
    }
    if (encoded) {
      bool written = true;
      for (const can::Frame& frame : frames) written = send(frame, report) && written;
      report.wire.written = written;
      report.wire.joints = planner::PerJoint<can::Setpoint>(frames.size());
      for (int j = 0; j < frames.size(); ++j) {
        if (auto wire = can::decodeSetpoint(frames[j])) report.wire.joints[j] = wire.value().setpoint;
      }
    } else {
      ++report.encode_errors;  // the streamer's limits are inside the frame's: not expected
    }
  }
  if (++ticks_since_status_ >= settings_.status_every_ticks) {
    ticks_since_status_ = 0;
    std::uint8_t bits = fault_bits;
    if (tick.gate_reason == GateReason::kStateStale) bits |= can::fault::kStateStale;
    if (failing_) bits |= can::fault::kCanWriteFailed;
    can::Status status;
    status.mode = tick.mode;
    status.request_id = can::requestIdLow16(tick.request_id);
    status.time_remaining_ms = can::saturateTimeRemainingMs(tick.remaining_s);
    status.fault_bits = bits;
    status.sequence = status_sequence_++;
    if (auto frame = can::encodeStatus(settings_.status_device, status)) {
      report.status_sent = send(frame.value(), report);
    } else {
      ++report.encode_errors;
    }
  }
  return report;
}

}  // namespace cyber::daemon

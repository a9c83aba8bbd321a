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
    const can::Setpoint elevator{tick.setpoints.position[0], tick.setpoints.velocity[0], tick.setpoints.volts[0],
                                 elevator_sequence_++};
    const can::Setpoint arm{tick.setpoints.position[1], tick.setpoints.velocity[1], tick.setpoints.volts[1],
                            arm_sequence_++};
    auto elevator_frame = can::encodeSetpoint(settings_.elevator_device, elevator);
    auto arm_frame = can::encodeSetpoint(settings_.arm_device, arm);
    if (elevator_frame && arm_frame) {
      const bool elevator_ok = send(elevator_frame.value(), report);
      const bool arm_ok = send(arm_frame.value(), report);
      auto elevator_wire = can::decodeSetpoint(elevator_frame.value());
      auto arm_wire = can::decodeSetpoint(arm_frame.value());
      if (elevator_wire && arm_wire) {
        report.wire.written = elevator_ok && arm_ok;
        report.wire.elevator = elevator_wire.value().setpoint;
        report.wire.arm = arm_wire.value().setpoint;
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

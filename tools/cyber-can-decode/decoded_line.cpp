#include "decoded_line.hpp"

#include <fmt/format.h>

#include <iterator>
#include <string_view>

#include "cyber/can/bus_error.hpp"
#include "cyber/can/frame_kind.hpp"
#include "cyber/can/frc_id.hpp"
#include "cyber/can/robot_frames.hpp"
#include "cyber/can/setpoint_codec.hpp"
#include "cyber/can/status_codec.hpp"

namespace cyber::tools {

namespace {

// All CSV columns; a row fills the ones that apply to its kind and leaves the others empty.
struct Row {
  std::string time_s, iface, kind, device, joint, seq, position, velocity, volts, mode, request_id, time_remaining_ms,
      fault_bits, red_alliance, enabled, autonomous, test, system_watchdog, id, data, error;
};

constexpr const char* kHeader =
    "time_s,iface,kind,device,joint,seq,position,velocity,volts,mode,request_id,"
    "time_remaining_ms,fault_bits,red_alliance,enabled,autonomous,test,system_watchdog,id,data,"
    "error";

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string joinCsv(const Row& r) {
  const std::string* fields[] = {
      &r.time_s,     &r.iface,        &r.kind,    &r.device,     &r.joint,      &r.seq,
      &r.position,   &r.velocity,     &r.volts,   &r.mode,       &r.request_id, &r.time_remaining_ms,
      &r.fault_bits, &r.red_alliance, &r.enabled, &r.autonomous, &r.test,       &r.system_watchdog,
      &r.id,         &r.data,         &r.error};
  std::string line;
  for (const std::string* field : fields) {
    if (!line.empty() || field != fields[0]) line += ',';
    line += csvField(*field);
  }
  return line;
}

std::string hexData(const can::Frame& frame) {
  if (frame.remote) return "R" + std::to_string(frame.dlc);
  std::string out;
  for (std::uint8_t i = 0; i < frame.dlc; ++i) fmt::format_to(std::back_inserter(out), "{:02X}", frame.data[i]);
  return out;
}

std::string hexId(const can::Frame& frame) {
  return frame.extended || frame.error ? fmt::format("{:08X}", frame.id) : fmt::format("{:03X}", frame.id);
}

std::string flag(bool value) { return value ? "1" : "0"; }

void fillSetpoint(const can::DeviceSetpoint& decoded, const JointDevices& joints, Row& row, std::string& text) {
  const auto& s = decoded.setpoint;
  int joint = -1;
  for (size_t j = 0; j < joints.devices.size() && joint < 0; ++j) {
    if (decoded.device == joints.devices[j]) joint = static_cast<int>(j);
  }
  row.joint = joint >= 0 ? joints.names[static_cast<size_t>(joint)] : "";
  row.seq = std::to_string(s.sequence);
  row.position = fmt::format("{:.5f}", s.position);
  row.velocity = fmt::format("{:.3f}", s.velocity);
  row.volts = fmt::format("{:.3f}", s.feedforward_volts);
  const std::string unit = joint >= 0 ? " " + joints.units[static_cast<size_t>(joint)] : "";
  const std::string rate = joint >= 0 ? unit + "/s" : "";
  text += (row.joint.empty() ? std::string() : " " + row.joint) + " dev " + row.device + " seq " + row.seq +
          " position " + row.position + unit + " velocity " + row.velocity + rate + " ff " + row.volts + " V";
}

void fillStatus(const can::DeviceStatus& decoded, Row& row, std::string& text) {
  const auto& s = decoded.status;
  row.seq = std::to_string(s.sequence);
  row.mode = std::string(can::toString(s.mode));
  row.request_id = std::to_string(s.request_id);
  row.time_remaining_ms = std::to_string(s.time_remaining_ms);
  row.fault_bits = fmt::format("0x{:02X}", s.fault_bits);
  text += " dev " + row.device + " seq " + row.seq + " mode " + row.mode + " request " + row.request_id +
          " remaining " + row.time_remaining_ms + " ms faults " + row.fault_bits;
}

void fillHeartbeat(const can::Heartbeat& h, Row& row, std::string& text) {
  row.red_alliance = flag(h.red_alliance);
  row.enabled = flag(h.enabled);
  row.autonomous = flag(h.autonomous);
  row.test = flag(h.test);
  row.system_watchdog = flag(h.system_watchdog);
  text += " enabled=" + row.enabled + " watchdog=" + row.system_watchdog + " red=" + row.red_alliance +
          " auto=" + row.autonomous + " test=" + row.test;
}

void fillBusError(const can::BusError& e, std::string& text) {
  if (e.bus_off) text += " bus-off";
  if (e.controller_problem) fmt::format_to(std::back_inserter(text), " controller(0x{:02X})", e.controller_status);
  if (e.tx_timeout) text += " tx-timeout";
  if (e.restarted) text += " restarted";
  if (e.other) text += " other";
}

}  // namespace

std::string csvHeader() { return kHeader; }

std::string decodeRecord(const can::LogRecord& record, const JointDevices& joints, OutputFormat format_kind,
                         DecodeCounts& counts) {
  const can::Frame& frame = record.frame;
  ++counts.frames;
  Row row;
  row.time_s = fmt::format("{}.{:06}", record.time.seconds, record.time.microseconds);
  row.iface = record.iface;
  row.id = hexId(frame);
  row.data = hexData(frame);
  const can::FrameKind kind = classify(frame);
  row.kind = std::string(can::toString(kind));
  std::string text = row.time_s + " " + row.iface + " " + row.kind;
  if (kind == can::FrameKind::kSetpoint || kind == can::FrameKind::kStatus) {
    row.device = std::to_string(can::unpackFrcId(frame.id).device);
  }

  // A decoder error sets `problem`: the frame has one of our ids but a bad payload.
  can::CodecError problem = can::CodecError::kOk;
  switch (kind) {
    case can::FrameKind::kSetpoint: {
      const auto decoded = can::decodeSetpoint(frame);
      if (decoded) {
        fillSetpoint(decoded.value(), joints, row, text);
      } else {
        problem = decoded.status();
      }
      break;
    }
    case can::FrameKind::kStatus: {
      const auto decoded = can::decodeStatus(frame);
      if (decoded) {
        fillStatus(decoded.value(), row, text);
      } else {
        problem = decoded.status();
      }
      break;
    }
    case can::FrameKind::kHeartbeat: {
      // The flags printed are the same in both controllers' layouts (docs/can-protocol.md).
      const auto decoded = can::decodeHeartbeat(frame, can::HeartbeatLayout::kRoboRio);
      if (decoded) {
        fillHeartbeat(decoded.value(), row, text);
      } else {
        problem = decoded.status();
      }
      break;
    }
    case can::FrameKind::kBroadcastDisable: text += " (stop all motion)"; break;
    case can::FrameKind::kBusError: {
      const auto decoded = can::decodeBusError(frame);
      if (decoded) fillBusError(decoded.value(), text);
      break;
    }
    case can::FrameKind::kOther: text += " " + row.id + "#" + row.data; break;
  }

  if (problem != can::CodecError::kOk) {
    ++counts.undecodable;
    row.kind = "undecodable";
    row.error = std::string(can::toString(problem));
    text = row.time_s + " " + row.iface + " undecodable " + std::string(can::toString(kind)) + " " + row.id + "#" +
           row.data + ": " + row.error;
  } else if (kind == can::FrameKind::kOther) {
    ++counts.other;
  } else {
    ++counts.decoded;
  }
  return format_kind == OutputFormat::kCsv ? joinCsv(row) : text;
}

}  // namespace cyber::tools

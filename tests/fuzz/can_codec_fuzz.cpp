// Fuzz target: the CAN codec (docs/can-protocol.md). The input's first 16 bytes are a kernel
// struct can_frame as a socket delivers it; the rest are values to encode.
// Properties:
//   - fromLinuxFrame gives a well-formed frame (or kWrongLength) that converts back one-to-one;
//   - classify agrees with the decoders: a frame of kind K decodes with K's decoder or fails
//     with a length/mode error, and no other decoder accepts it;
//   - a decoded setpoint, status or heartbeat encodes back to the very same frame;
//   - encodeSetpoint succeeds exactly when every value rounds to a count that fits its field,
//     and then decode(encode(x)) = x within half a count of each scale.

#include <linux/can.h>

#include <array>
#include <cmath>
#include <cstring>
#include <utility>

#include "cyber/can/bus_error.hpp"
#include "cyber/can/frame_kind.hpp"
#include "cyber/can/frc_id.hpp"
#include "cyber/can/linux_frame.hpp"
#include "cyber/can/robot_frames.hpp"
#include "cyber/can/setpoint_codec.hpp"
#include "cyber/can/status_codec.hpp"
#include "fuzz_check.hpp"
#include "fuzz_input.hpp"

namespace {

using namespace cyber::can;

void checkReceived(const Frame& frame) {
  CYBER_FUZZ_CHECK(isWellFormed(frame));
  const can_frame raw = toLinuxFrame(frame);
  const auto back = fromLinuxFrame(raw);
  CYBER_FUZZ_CHECK(back && back.value() == frame);

  const FrameKind kind = classify(frame);
  const auto setpoint = decodeSetpoint(frame);
  const auto status = decodeStatus(frame);
  const auto heartbeat = decodeHeartbeat(frame, HeartbeatLayout::kRoboRio);
  const auto heartbeat_systemcore = decodeHeartbeat(frame, HeartbeatLayout::kSystemcore);
  CYBER_FUZZ_CHECK(heartbeat.ok() == heartbeat_systemcore.ok());
  const auto bus_error = decodeBusError(frame);
  CYBER_FUZZ_CHECK(!setpoint || kind == FrameKind::kSetpoint);
  CYBER_FUZZ_CHECK(!status || kind == FrameKind::kStatus);
  CYBER_FUZZ_CHECK(!heartbeat || kind == FrameKind::kHeartbeat);
  CYBER_FUZZ_CHECK(!bus_error || kind == FrameKind::kBusError);
  CYBER_FUZZ_CHECK(isBroadcastDisable(frame) == (kind == FrameKind::kBroadcastDisable));
  // A known id with a bad payload (or a remote request for it) is a decode error, not another kind.
  const auto payload_error = [](CodecError e) {
    return e == CodecError::kWrongLength || e == CodecError::kRemoteFrame || e == CodecError::kBadMode;
  };
  if (kind == FrameKind::kSetpoint && !setpoint) CYBER_FUZZ_CHECK(payload_error(setpoint.status()));
  if (kind == FrameKind::kStatus && !status) CYBER_FUZZ_CHECK(payload_error(status.status()));
  if (kind == FrameKind::kHeartbeat && !heartbeat) CYBER_FUZZ_CHECK(payload_error(heartbeat.status()));

  if (setpoint) {
    const auto again = encodeSetpoint(setpoint.value().device, setpoint.value().setpoint);
    CYBER_FUZZ_CHECK(again && again.value() == frame);
  }
  if (status) {
    const auto again = encodeStatus(status.value().device, status.value().status);
    // Byte 6 is reserved: encode writes 0, decode ignores it.
    Frame expected = frame;
    expected.data[6] = 0;
    CYBER_FUZZ_CHECK(again && again.value() == expected);
  }
  if (heartbeat) {
    // encodeHeartbeat writes what decode reads (the flags, the replay number, Systemcore's
    // override) and zeros elsewhere; the two layouts differ only in byte 5's top bit.
    for (const auto& [layout, decoded] : {std::pair{HeartbeatLayout::kRoboRio, heartbeat.value()},
                                          std::pair{HeartbeatLayout::kSystemcore, heartbeat_systemcore.value()}}) {
      const Frame again = encodeHeartbeat(decoded, layout);
      CYBER_FUZZ_CHECK(again.id == frame.id && again.extended && again.dlc == frame.dlc);
      CYBER_FUZZ_CHECK(decodeHeartbeat(again, layout).value() == decoded);
    }
    Heartbeat flags_only = heartbeat_systemcore.value();
    flags_only.replay_number = heartbeat.value().replay_number;
    flags_only.ftc_motor_override = false;
    CYBER_FUZZ_CHECK(flags_only == heartbeat.value());
  }
}

// Whether `value` * scale rounds (halves away from zero) to a count within [lo, hi].
bool fits(double value, double scale, double lo, double hi) {
  const double scaled = value * scale;
  if (!std::isfinite(scaled)) return false;
  const double rounded = std::round(scaled);
  return rounded >= lo && rounded <= hi;
}

void checkEncode(cyber::fuzz::FuzzInput& in) {
  const auto device = in.take<std::uint8_t>();
  Setpoint setpoint;
  setpoint.position = in.take<double>();
  setpoint.velocity = in.take<double>();
  setpoint.feedforward_volts = in.take<double>();
  setpoint.sequence = in.take<std::uint8_t>();
  const bool position_fits = fits(setpoint.position, kPositionCountsPerUnit, kPositionMinCount, kPositionMaxCount);
  const bool velocity_fits = fits(setpoint.velocity, kVelocityCountsPerUnit, -32768, 32767);
  const bool volts_fit = fits(setpoint.feedforward_volts, kVoltageCountsPerVolt, -32768, 32767);
  const auto frame = encodeSetpoint(device, setpoint);
  const bool should_fit = device <= kMaxDeviceNumber && position_fits && velocity_fits && volts_fit;
  CYBER_FUZZ_CHECK(frame.ok() == should_fit);
  if (frame) {
    CYBER_FUZZ_CHECK(isWellFormed(frame.value()) && classify(frame.value()) == FrameKind::kSetpoint);
    const auto decoded = decodeSetpoint(frame.value());
    CYBER_FUZZ_CHECK(decoded && decoded.value().device == device);
    const Setpoint& back = decoded.value().setpoint;
    // Half a count, plus the rounding of the scaled double itself.
    CYBER_FUZZ_CHECK(std::fabs(back.position - setpoint.position) <= 0.5 / kPositionCountsPerUnit * (1 + 1e-9));
    CYBER_FUZZ_CHECK(std::fabs(back.velocity - setpoint.velocity) <= 0.5 / kVelocityCountsPerUnit * (1 + 1e-9));
    CYBER_FUZZ_CHECK(std::fabs(back.feedforward_volts - setpoint.feedforward_volts) <=
                     0.5 / kVoltageCountsPerVolt * (1 + 1e-9));
    CYBER_FUZZ_CHECK(back.sequence == setpoint.sequence);
  }

  const auto status_device = in.take<std::uint8_t>();
  Status status;
  status.mode = static_cast<Mode>(in.take<std::uint8_t>());
  status.request_id = in.take<std::uint16_t>();
  status.time_remaining_ms = in.take<std::uint16_t>();
  status.fault_bits = in.take<std::uint8_t>();
  status.sequence = in.take<std::uint8_t>();
  const auto status_frame = encodeStatus(status_device, status);
  CYBER_FUZZ_CHECK(status_frame.ok() ==
                   (status_device <= kMaxDeviceNumber &&
                    static_cast<std::uint8_t>(status.mode) <= static_cast<std::uint8_t>(kLastMode)));
  if (status_frame) {
    const auto decoded = decodeStatus(status_frame.value());
    CYBER_FUZZ_CHECK(decoded && decoded.value().device == status_device && decoded.value().status == status);
  }

  const auto flags = in.take<std::uint8_t>();
  const Heartbeat heartbeat{(flags & 1) != 0, (flags & 2) != 0, (flags & 4) != 0, (flags & 8) != 0, (flags & 16) != 0};
  const auto decoded = decodeHeartbeat(encodeHeartbeat(heartbeat), HeartbeatLayout::kRoboRio);
  CYBER_FUZZ_CHECK(decoded && decoded.value() == heartbeat);

  const double seconds = in.take<double>();
  const std::uint16_t ms = saturateTimeRemainingMs(seconds);
  if (!(seconds > 0.0)) CYBER_FUZZ_CHECK(ms == 0);
  if (seconds >= 65.535) CYBER_FUZZ_CHECK(ms == 65535);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cyber::fuzz::FuzzInput in(data, size);
  can_frame raw;
  static_assert(sizeof raw == 16);
  std::memset(&raw, 0, sizeof raw);
  raw.can_id = in.take<canid_t>();
  raw.len = in.take<std::uint8_t>();
  raw.__pad = in.take<std::uint8_t>();
  raw.__res0 = in.take<std::uint8_t>();
  raw.len8_dlc = in.take<std::uint8_t>();
  // One read for the payload: byte by byte, g++ 12 -O3 sees a false -Wstringop-overflow.
  const auto payload = in.take<std::array<std::uint8_t, CAN_MAX_DLEN>>();
  std::memcpy(raw.data, payload.data(), sizeof raw.data);
  const auto frame = fromLinuxFrame(raw);
  if (frame) {
    checkReceived(frame.value());
  } else {
    CYBER_FUZZ_CHECK(raw.len > CAN_MAX_DLEN);
  }
  checkEncode(in);
  return 0;
}

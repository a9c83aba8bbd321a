#include "cyber/can/status_codec.hpp"

#include <cmath>

#include "cyber/can/frc_id.hpp"
#include "wire.hpp"

namespace cyber::can {

namespace {
bool isDefinedMode(std::uint8_t mode) { return mode <= static_cast<std::uint8_t>(kLastMode); }
}  // namespace

std::string_view toString(Mode mode) {
  switch (mode) {
    case Mode::kNoState: return "no-state";
    case Mode::kHolding: return "holding";
    case Mode::kMoving: return "moving";
    case Mode::kFault: return "fault";
    case Mode::kRobotDisabled: return "robot-disabled";
    case Mode::kReleased: return "released";
  }
  return "undefined";
}

std::uint16_t saturateTimeRemainingMs(double seconds) {
  if (!(seconds > 0.0)) return 0;  // also NaN
  // The 1e-6 ms slack keeps decimal inputs such as 0.85 s from rounding up to 851 ms.
  const double ms = std::ceil(seconds * 1000.0 - 1e-6);
  if (ms >= 65535.0) return 65535;
  return static_cast<std::uint16_t>(ms);
}

Result<Frame, CodecError> encodeStatus(std::uint8_t device, const Status& status) {
  if (device > kMaxDeviceNumber) return CodecError::kDeviceOutOfRange;
  const auto mode = static_cast<std::uint8_t>(status.mode);
  if (!isDefinedMode(mode)) return CodecError::kBadMode;

  Frame frame;
  frame.id = teamFrameId(kStatusApiClass, kStatusApiIndex, device);
  frame.extended = true;
  frame.dlc = kStatusLength;
  frame.data[0] = mode;
  wire::putU16(frame, 1, status.request_id);
  wire::putU16(frame, 3, status.time_remaining_ms);
  frame.data[5] = status.fault_bits;
  frame.data[6] = 0;
  frame.data[7] = status.sequence;
  return frame;
}

Result<DeviceStatus, CodecError> decodeStatus(const Frame& frame) {
  const FrcId id = unpackFrcId(frame.id);
  const bool id_matches = id.device_type == kDeviceTypeMiscellaneous && id.manufacturer == kManufacturerTeamUse &&
                          id.api_class == kStatusApiClass && id.api_index == kStatusApiIndex;
  if (const auto problem = wire::checkDataFrame(frame, id_matches, kStatusLength)) {
    return *problem;
  }
  if (!isDefinedMode(frame.data[0])) return CodecError::kBadMode;
  DeviceStatus out;
  out.device = id.device;
  out.status.mode = static_cast<Mode>(frame.data[0]);
  out.status.request_id = wire::getU16(frame, 1);
  out.status.time_remaining_ms = wire::getU16(frame, 3);
  out.status.fault_bits = frame.data[5];
  out.status.sequence = frame.data[7];
  return out;
}

}  // namespace cyber::can

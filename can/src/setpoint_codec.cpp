#include "cyber/can/setpoint_codec.hpp"

#include "cyber/can/frc_id.hpp"
#include "wire.hpp"

namespace cyber::can {

Result<Frame, CodecError> encodeSetpoint(std::uint8_t device, const Setpoint& setpoint) {
  if (device > kMaxDeviceNumber) return CodecError::kDeviceOutOfRange;
  const auto position = wire::toCounts(setpoint.position, kPositionCountsPerUnit, kPositionMinCount, kPositionMaxCount);
  if (!position) return CodecError::kPositionOutOfRange;
  const auto velocity = wire::toCounts(setpoint.velocity, kVelocityCountsPerUnit, kInt16MinCount, kInt16MaxCount);
  if (!velocity) return CodecError::kVelocityOutOfRange;
  const auto millivolts =
      wire::toCounts(setpoint.feedforward_volts, kVoltageCountsPerVolt, kInt16MinCount, kInt16MaxCount);
  if (!millivolts) return CodecError::kVoltageOutOfRange;

  Frame frame;
  frame.id = teamFrameId(kSetpointApiClass, kSetpointApiIndex, device);
  frame.extended = true;
  frame.dlc = kSetpointLength;
  wire::putI24(frame, 0, *position);
  wire::putI16(frame, 3, static_cast<std::int16_t>(*velocity));
  wire::putI16(frame, 5, static_cast<std::int16_t>(*millivolts));
  frame.data[7] = setpoint.sequence;
  return frame;
}

Result<DeviceSetpoint, CodecError> decodeSetpoint(const Frame& frame) {
  const FrcId id = unpackFrcId(frame.id);
  const bool id_matches = id.device_type == kDeviceTypeMiscellaneous && id.manufacturer == kManufacturerTeamUse &&
                          id.api_class == kSetpointApiClass && id.api_index == kSetpointApiIndex;
  if (const auto problem = wire::checkDataFrame(frame, id_matches, kSetpointLength)) {
    return *problem;
  }
  // Division (not multiplication by 1e-5) gives the double nearest the exact decimal value.
  DeviceSetpoint out;
  out.device = id.device;
  out.setpoint.position = wire::getI24(frame, 0) / kPositionCountsPerUnit;
  out.setpoint.velocity = wire::getI16(frame, 3) / kVelocityCountsPerUnit;
  out.setpoint.feedforward_volts = wire::getI16(frame, 5) / kVoltageCountsPerVolt;
  out.setpoint.sequence = frame.data[7];
  return out;
}

}  // namespace cyber::can

#pragma once
// FRC CAN addressing (docs/can-protocol.md): a 29-bit id split into device type (5 bits),
// manufacturer (8), API class (6), API index (4) and device number (6).

#include <cstdint>

namespace cyber::can {

inline constexpr std::uint8_t kDeviceTypeMiscellaneous = 10;
inline constexpr std::uint8_t kManufacturerTeamUse = 8;
inline constexpr std::uint8_t kMaxDeviceNumber = 63;

inline constexpr std::uint8_t kSetpointApiClass = 1;
inline constexpr std::uint8_t kSetpointApiIndex = 0;
inline constexpr std::uint8_t kStatusApiClass = 2;
inline constexpr std::uint8_t kStatusApiIndex = 0;

// The roboRIO's universal heartbeat and the broadcast disable message (both extended ids).
inline constexpr std::uint32_t kHeartbeatId = 0x01011840u;
inline constexpr std::uint32_t kBroadcastDisableId = 0u;

struct FrcId {
  std::uint8_t device_type = 0;   // 0..31
  std::uint8_t manufacturer = 0;  // 0..255
  std::uint8_t api_class = 0;     // 0..63
  std::uint8_t api_index = 0;     // 0..15
  std::uint8_t device = 0;        // 0..63

  bool operator==(const FrcId&) const = default;
};

// The 10-bit API id WPILib's CAN class takes: (api_class << 4) | api_index.
constexpr std::uint16_t apiId(std::uint8_t api_class, std::uint8_t api_index) {
  return static_cast<std::uint16_t>(((api_class & 0x3Fu) << 4) | (api_index & 0x0Fu));
}

// Packs the fields; bits beyond each field's width are dropped (callers validate device numbers
// through the codec, which reports kDeviceOutOfRange instead).
constexpr std::uint32_t packFrcId(const FrcId& id) {
  return (std::uint32_t{id.device_type & 0x1Fu} << 24) | (std::uint32_t{id.manufacturer} << 16) |
         (std::uint32_t{apiId(id.api_class, id.api_index)} << 6) | (id.device & 0x3Fu);
}

constexpr FrcId unpackFrcId(std::uint32_t id) {
  return FrcId{static_cast<std::uint8_t>((id >> 24) & 0x1Fu), static_cast<std::uint8_t>((id >> 16) & 0xFFu),
               static_cast<std::uint8_t>((id >> 10) & 0x3Fu), static_cast<std::uint8_t>((id >> 6) & 0x0Fu),
               static_cast<std::uint8_t>(id & 0x3Fu)};
}

// Id of one of our team-use frames (device type 10, manufacturer 8).
constexpr std::uint32_t teamFrameId(std::uint8_t api_class, std::uint8_t api_index, std::uint8_t device) {
  return packFrcId(FrcId{kDeviceTypeMiscellaneous, kManufacturerTeamUse, api_class, api_index, device});
}

}  // namespace cyber::can

#pragma once
// WPILib's Pose3d struct (translation x, y, z in m; rotation as a quaternion w, x, y, z), packed
// as struct.adoc lays it out, and the schemas that describe it to AdvantageScope.

#include <cstdint>
#include <span>
#include <vector>

#include "cyber/wpilog/wpilog_writer.hpp"

namespace cyber::wpilog {

struct Pose3d {
  double x = 0, y = 0, z = 0;             // m
  double qw = 1, qx = 0, qy = 0, qz = 0;  // unit quaternion
};

constexpr size_t kPose3dBytes = 7 * 8;

// The four schemas a "struct:Pose3d" or "struct:Pose3d[]" entry needs, published once per log.
void addPose3dSchemas(Writer& writer, uint64_t timestamp_us);
std::vector<uint8_t> packPose3dArray(std::span<const Pose3d> poses);
// nullopt-like: false when the payload is not a whole number of poses.
bool unpackPose3dArray(std::span<const uint8_t> payload, std::vector<Pose3d>* poses);

}  // namespace cyber::wpilog

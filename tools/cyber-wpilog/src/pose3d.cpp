#include "cyber/wpilog/pose3d.hpp"

#include "cyber/wpilog/wpilog_reader.hpp"

namespace cyber::wpilog {

void addPose3dSchemas(Writer& writer, uint64_t timestamp_us) {
  writer.addStructSchema("Quaternion", "double w;double x;double y;double z", timestamp_us);
  writer.addStructSchema("Rotation3d", "Quaternion q", timestamp_us);
  writer.addStructSchema("Translation3d", "double x;double y;double z", timestamp_us);
  writer.addStructSchema("Pose3d", "Translation3d translation;Rotation3d rotation", timestamp_us);
}

std::vector<uint8_t> packPose3dArray(std::span<const Pose3d> poses) {
  std::vector<uint8_t> out;
  for (const Pose3d& p : poses) {
    for (double v : {p.x, p.y, p.z, p.qw, p.qx, p.qy, p.qz}) putF64(out, v);
  }
  return out;
}

bool unpackPose3dArray(std::span<const uint8_t> payload, std::vector<Pose3d>* poses) {
  const auto values = asDoubleArray(payload);
  if (!values || payload.size() % kPose3dBytes != 0) return false;
  poses->clear();
  for (size_t i = 0; i < values->size(); i += 7) {
    const double* v = values->data() + i;
    poses->push_back(Pose3d{v[0], v[1], v[2], v[3], v[4], v[5], v[6]});
  }
  return true;
}

}  // namespace cyber::wpilog

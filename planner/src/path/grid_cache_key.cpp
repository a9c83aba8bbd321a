#include "path/grid_cache_key.hpp"

#include <bit>

namespace cyber::planner {
namespace {

// Written by planner/CMakeLists.txt for this file alone.
#ifndef CYBER_PROJECT_VERSION
#error "CYBER_PROJECT_VERSION is defined by planner/CMakeLists.txt"
#endif

constexpr std::uint64_t kFnvPrime = 0x100000001b3ULL;
constexpr int kBitsPerByte = 8;
constexpr std::uint64_t kLowByte = 0xff;

void polygon(Fnv1a64& hash, const ConvexPolygon& polygon) {
  hash.u64(static_cast<std::uint64_t>(polygon.size()));
  for (const Point2& v : polygon.vertices()) {
    hash.f64(v.x());
    hash.f64(v.y());
  }
}

template <class Named>
void polygonsOf(Fnv1a64& hash, const std::vector<Named>& parts) {
  hash.u64(parts.size());
  for (const Named& part : parts) {
    hash.u64(static_cast<std::uint64_t>(part.joint));
    hash.u64(part.polygons.size());
    for (const ConvexPolygon& p : part.polygons) polygon(hash, p);
  }
}

void obstacles(Fnv1a64& hash, const std::vector<NamedPolygon>& list) {
  hash.u64(list.size());
  for (const NamedPolygon& obstacle : list) polygon(hash, obstacle.polygon);
}

}  // namespace

void Fnv1a64::bytes(std::span<const std::uint8_t> data) {
  for (const std::uint8_t byte : data) {
    state_ ^= byte;
    state_ *= kFnvPrime;
  }
}

void Fnv1a64::u64(std::uint64_t value) {
  for (int i = 0; i < static_cast<int>(sizeof value); ++i) {
    const auto byte = static_cast<std::uint8_t>((value >> (kBitsPerByte * i)) & kLowByte);
    bytes(std::span(&byte, 1));
  }
}

void Fnv1a64::f64(double value) { u64(std::bit_cast<std::uint64_t>(value)); }

void Fnv1a64::text(std::string_view value) {
  u64(value.size());
  for (const char c : value) u64(static_cast<unsigned char>(c));
}

std::uint64_t gridCacheKey(const RobotModel& model, const Scene& scene, const JointRange& band) {
  Fnv1a64 hash;
  hash.u64(kGridFormatVersion);
  hash.text(CYBER_PROJECT_VERSION);
  hash.text(__VERSION__);  // the compiler
  hash.u64(sizeof(void*));
  for (const ChainJoint& joint : model.joints) {
    hash.u64(static_cast<std::uint64_t>(joint.type));
    hash.f64(joint.origin_m.x());
    hash.f64(joint.origin_m.y());
    hash.f64(joint.axis_rad);
    hash.f64(joint.range.min);
    hash.f64(joint.range.max);
  }
  polygonsOf(hash, model.links);
  polygonsOf(hash, model.pieces);
  obstacles(hash, scene.obstacles);
  obstacles(hash, scene.fixed);
  hash.f64(scene.offset_range_m.min);
  hash.f64(scene.offset_range_m.max);
  hash.f64(band.min);
  hash.f64(band.max);
  hash.f64(model.clearance_m);
  const PlannerSettings& settings = model.planner;
  for (int j = 0; j < settings.metric.size(); ++j) hash.f64(settings.metric[j]);
  for (int j = 0; j < settings.grid.step.size(); ++j) hash.f64(settings.grid.step[j]);
  hash.f64(settings.grid.joint_limit_margin);
  hash.f64(settings.search.potential_weight);
  hash.f64(settings.search.potential_range);
  hash.f64(settings.search.offset_band_clearances);
  return hash.value();
}

}  // namespace cyber::planner

#pragma once
// The key of a band's grids in the grid cache (docs/design.md, "The grid cache"): a 64-bit
// FNV-1a hash over a canonical byte serialisation of everything CSpaceGrid::build reads, so a
// cached grid is used only for the inputs it was built from.

#include <cstdint>
#include <span>
#include <string_view>

#include "cyber/planner/robot_model.hpp"

namespace cyber::planner {

// The version of the grids: bumped by hand whenever the code that builds them, or the cache file's
// layout, changes what a key stands for. GridCacheKey.TheReferenceGridsAreThoseOfThisVersion fails
// until it is bumped (and the test's fingerprint recorded) when the reference robot's grids change.
inline constexpr std::uint32_t kGridFormatVersion = 2;

// FNV-1a, 64 bits: fixed by its definition, the same on every machine and build.
class Fnv1a64 {
 public:
  void bytes(std::span<const std::uint8_t> data);
  void u64(std::uint64_t value);  // little-endian, whatever the machine's order
  void f64(double value);         // its IEEE bits: -0.0 and 0.0 differ (a rebuild, never a wrong grid)
  void text(std::string_view value);
  [[nodiscard]] std::uint64_t value() const { return state_; }

 private:
  std::uint64_t state_ = 0xcbf29ce484222325ULL;
};

// Of the grids of `scene`'s `band` of offsets ({0, 0}: the scene as drawn) for every held set:
// the joints' chain and ranges, the links' and pieces' polygons, the scene's obstacles, the
// clearance, the grid and search settings and metric, kGridFormatVersion, the project's version
// and the compiler that built this planner (a floating-point result may differ between them).
// Names do not enter: renaming a scene keeps its grids.
[[nodiscard]] std::uint64_t gridCacheKey(const RobotModel& model, const Scene& scene, const JointRange& band);

}  // namespace cyber::planner

#pragma once
// Configuration-space vectors. q = (t, theta): carriage travel [m] and arm angle [rad].

#include <Eigen/Core>

namespace cyber::planner {

using JointVector = Eigen::Vector2d;  // (elevator_m, arm_rad) or their rates
using Point2 = Eigen::Vector2d;       // a point in the 2-D side view [m]

inline constexpr int kElevator = 0;
inline constexpr int kArm = 1;
inline constexpr int kJointCount = 2;

// Game pieces held by the mechanism. Each held piece adds polygons; none removes any.
struct HeldPieces {
  bool coral = false;
  bool algae = false;

  // 0 none, 1 coral, 2 algae, 3 both: index of the per-piece-set grids.
  [[nodiscard]] int index() const { return (coral ? 1 : 0) | (algae ? 2 : 0); }
  static HeldPieces fromIndex(int i) { return HeldPieces{(i & 1) != 0, (i & 2) != 0}; }
  friend bool operator==(const HeldPieces&, const HeldPieces&) = default;
};
inline constexpr int kPieceSetCount = 4;

}  // namespace cyber::planner

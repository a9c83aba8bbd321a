#pragma once
// Configuration-space vectors q = (q0, q1): the two joints of the chain in chain order, each in
// its own unit (m for a prismatic joint, rad for a revolute one; docs/algorithm.md section 1).

#include <cstdint>

#include <Eigen/Core>

namespace cyber::planner {

using JointVector = Eigen::Vector2d;  // joint positions (or their rates), chain order
using Point2 = Eigen::Vector2d;       // a point in the 2-D side view [m]

inline constexpr int kJointCount = 2;

// The game pieces held, as a set of indices into RobotModel::pieces. Each held piece adds
// polygons; none removes any.
struct HeldPieces {
  std::uint32_t bits = 0;

  // The grids and collision worlds are made for every set at start-up (docs/algorithm.md
  // section 2), so the number of named pieces is bounded.
  static constexpr int kMaxPieces = 4;

  [[nodiscard]] bool holds(int piece) const { return ((bits >> piece) & 1U) != 0; }
  [[nodiscard]] HeldPieces with(int piece) const { return HeldPieces{bits | (1U << piece)}; }
  [[nodiscard]] bool empty() const { return bits == 0; }
  // Index of the per-piece-set grids and worlds: 0 .. setCount(pieces) - 1.
  [[nodiscard]] int index() const { return static_cast<int>(bits); }
  static HeldPieces fromIndex(int i) { return HeldPieces{static_cast<std::uint32_t>(i)}; }
  // How many sets `piece_count` named pieces make.
  static constexpr int setCount(int piece_count) { return 1 << piece_count; }
  friend bool operator==(const HeldPieces&, const HeldPieces&) = default;
};

}  // namespace cyber::planner

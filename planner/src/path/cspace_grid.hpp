#pragma once
// The configuration-space grid of algorithm.md section 2.1: nodes over the joint box, the nodes
// where the robot is too close to an obstacle (blocked), and a potential that decays with the
// weighted distance from blocked nodes (a dynamic-programming distance transform).

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

// Nodes min, min + step, ..., min + (count - 1) step; the last node is the range's max.
struct GridAxis {
  double min = 0.0;
  double step = 1.0;
  int count = 1;

  [[nodiscard]] double at(int i) const { return min + step * i; }
  // The fewest nodes with spacing <= max_step that cover [range.min + inset, range.max - inset].
  static GridAxis covering(const JointRange& range, double max_step, double inset = 0.0);
};

// A blocked region that touches no edge of the grid: an obstacle of C-space a path can pass on
// either side. Its ray runs up (increasing second-joint index) from between nodes (i, j) and (i + 1, j),
// both in the region (a region with no two such nodes is left out), to the grid's edge; a path's
// side of the hole is the parity of its crossings of the ray (two paths with the same ends and
// different parities cannot be deformed into each other without crossing the hole).
struct GridHole {
  int i = 0;
  int j = 0;
  int cells = 0;  // blocked nodes in the region
};

class CSpaceGrid {
 public:
  CSpaceGrid() = default;
  // From a blocked mask (cell = i_first * second.count + i_second); every step between free nodes is
  // free. Computes the potential.
  CSpaceGrid(GridAxis first, GridAxis second, std::vector<std::uint8_t> blocked, const JointVector& metric,
             const SearchSettings& search);

  // The grid of one collision world. A node is blocked when d(node) < clearance. A step between
  // two free nodes is free when it keeps d >= clearance along its whole length: certain without a
  // check when both ends have d >= clearance + L(step)/2 (d is Lipschitz, see
  // CollisionWorld::lipschitzBound, and every point of the step is within half of it of an end),
  // otherwise decided by a continuous segment check. Only nodes near obstacles need that check.
  static CSpaceGrid build(const CollisionWorld& world, const RobotModel& model);

  // What a grid cache stores of a built grid (path/grid_cache.hpp): a byte per node, the node's
  // forward steps (stepFree's bits) and kPackedBlocked when it is blocked; the rest is derived.
  static constexpr std::uint8_t kPackedBlocked = 0x80;
  [[nodiscard]] std::vector<std::uint8_t> packedNodes() const;
  // The grid whose packedNodes() these are, for a model with these axes and settings, made as
  // build() makes it from its nodes and steps. nullopt for bytes no built grid has: a wrong count,
  // unknown bits, or a step that leaves the grid or touches a blocked node.
  static std::optional<CSpaceGrid> fromPackedNodes(GridAxis first, GridAxis second, std::span<const std::uint8_t> nodes,
                                                   const RobotModel& model, int checked_steps);

  [[nodiscard]] int cellCount() const { return first_.count * second_.count; }
  [[nodiscard]] int cell(int i_first, int i_second) const { return i_first * second_.count + i_second; }
  [[nodiscard]] int firstIndex(int cell) const { return cell / second_.count; }
  [[nodiscard]] int secondIndex(int cell) const { return cell % second_.count; }
  [[nodiscard]] JointVector node(int cell) const {
    return JointVector(first_.at(firstIndex(cell)), second_.at(secondIndex(cell)));
  }
  [[nodiscard]] bool blocked(int cell) const { return blocked_[static_cast<size_t>(cell)] != 0; }
  // Whether the step from cell by (di, dj), each in {-1, 0, 1}, not both 0, stays clear. The
  // target must be inside the grid; blocked ends make the step blocked.
  [[nodiscard]] bool stepFree(int cell, int di, int dj) const {
    // Steps are stored once, at the end they leave in the forward directions (+1, -1), (+1, 0),
    // (+1, +1) and (0, +1); the others are looked up at their target.
    const int bit = kStepBit[di + 1][dj + 1];
    if (bit >= 0) return (steps_[static_cast<size_t>(cell)] >> bit) & 1U;
    const int target = cell + di * second_.count + dj;
    return (steps_[static_cast<size_t>(target)] >> kStepBit[1 - di][1 - dj]) & 1U;
  }
  // In [0, 1]: 1 on blocked nodes, falling to 0 at potential_range (weighted) from them.
  [[nodiscard]] double potential(int cell) const { return potential_[static_cast<size_t>(cell)]; }
  [[nodiscard]] const GridAxis& firstAxis() const { return first_; }
  [[nodiscard]] const GridAxis& secondAxis() const { return second_; }
  [[nodiscard]] const JointVector& metric() const { return metric_; }
  [[nodiscard]] double potentialWeight() const { return potential_weight_; }
  [[nodiscard]] double clearance_m() const { return clearance_m_; }
  // The holes, largest first.
  [[nodiscard]] const std::vector<GridHole>& holes() const { return holes_; }
  // Whether the step from cell by (di, dj) crosses the hole's ray.
  [[nodiscard]] bool crossesRay(const GridHole& hole, int cell, int di, int dj) const {
    const int i = firstIndex(cell);
    if (std::min(i, i + di) != hole.i || std::max(i, i + di) != hole.i + 1) return false;
    return 2 * secondIndex(cell) + dj > 2 * hole.j;
  }
  // The connected region of free nodes (through free steps) a free node belongs to; -1 when
  // blocked. Nodes of different regions have no path between them.
  [[nodiscard]] int region(int cell) const { return region_[static_cast<size_t>(cell)]; }
  // Steps that needed a continuous check when the grid was built.
  [[nodiscard]] int checkedStepCount() const { return checked_steps_; }
  [[nodiscard]] int blockedCount() const;
  // Weighted length of a step of (di, dj) nodes.
  [[nodiscard]] double stepLength(int di, int dj) const;
  // The node with the largest indices <= q's (clamped to the grid).
  [[nodiscard]] int lowerCorner(const JointVector& q) const;

 private:
  void computePotential(double range);
  void allowAllStepsBetweenFreeNodes();
  void findHoles();
  void labelRegions();

  // kStepBit[di + 1][dj + 1]: bit of a forward step, -1 for the backward ones.
  static constexpr int kStepBit[3][3] = {{-1, -1, -1}, {-1, -1, 3}, {0, 1, 2}};

  GridAxis first_;
  GridAxis second_;
  std::vector<std::uint8_t> blocked_;
  std::vector<std::uint8_t> steps_;  // bit per forward step, see stepFree
  std::vector<float> potential_;
  std::vector<int> region_;  // see region()
  std::vector<GridHole> holes_;
  JointVector metric_ = JointVector(1.0, 1.0);
  double potential_weight_ = 0.0;
  double clearance_m_ = 0.0;
  int checked_steps_ = 0;
};

}  // namespace cyber::planner

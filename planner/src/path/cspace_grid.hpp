#pragma once
// The configuration-space grid of algorithm.md section 2.1: nodes over the joint box, the nodes
// where the robot is too close to an obstacle (blocked), and a potential that decays with the
// weighted distance from blocked nodes (a dynamic-programming distance transform).

#include <algorithm>
#include <array>
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

// A node's indices, one per axis (entries past the grid's dimensions are 0).
using GridIndex = std::array<int, kMaxJoints>;

// One of the 3^N - 1 steps from a node to its neighbours: -1, 0 or +1 on each axis. A step is
// stored once, as a bit of the node it leaves when its first non-zero change is +1 (forward), and
// looked up at its target otherwise.
struct GridStep {
  GridIndex delta{};
  int cell_delta = 0;  // of the cell index
  int bit = -1;        // the forward step's bit at the node it leaves; -1 for a backward step
  int reverse = 0;     // index of the opposite step in CSpaceGrid::steps()
};

// A blocked region of a two-joint grid that touches no edge of the grid: an obstacle of C-space a
// path can pass on either side. Its ray runs up (increasing second-joint index) from between nodes
// (i, j) and (i + 1, j), both in the region (a region with no two such nodes is left out), to the
// grid's edge; a path's side of the hole is the parity of its crossings of the ray (two paths with
// the same ends and different parities cannot be deformed into each other without crossing the
// hole). In three dimensions a path goes round an obstacle in more than two ways, so a grid of
// three joints has none (docs/algorithm.md section 2.6).
struct GridHole {
  int i = 0;
  int j = 0;
  int cells = 0;  // blocked nodes in the region
};

class CSpaceGrid {
 public:
  CSpaceGrid() = default;
  // From a blocked mask (cell = sum of index times stride, the last axis fastest); every step
  // between free nodes is free. Computes the potential.
  CSpaceGrid(const PerJoint<GridAxis>& axes, std::vector<std::uint8_t> blocked, const JointVector& metric,
             const SearchSettings& search);

  // The grid of one collision world. A node is blocked when d(node) < clearance. A step between
  // two free nodes is free when it keeps d >= clearance along its whole length: certain without a
  // check when both ends have d >= clearance + L(step)/2 (d is Lipschitz, see
  // CollisionWorld::lipschitzBound, and every point of the step is within half of it of an end),
  // otherwise decided by a continuous segment check. Only nodes near obstacles need that check.
  static CSpaceGrid build(const CollisionWorld& world, const RobotModel& model);
  // The axes build() lays over the model's joints.
  static PerJoint<GridAxis> axesOf(const RobotModel& model);

  // What a grid cache stores of a built grid (path/grid_cache.hpp): per node, its forward steps
  // (stepFree's bits) and the top bit of its bytesPerNode() bytes (least significant first) when
  // it is blocked; the rest is derived.
  [[nodiscard]] int bytesPerNode() const { return packedBytesPerNode(dimensions()); }
  static int packedBytesPerNode(int dimensions) { return dimensions <= 2 ? 1 : 2; }
  [[nodiscard]] std::vector<std::uint8_t> packedNodes() const;
  // The grid whose packedNodes() these are, for a model with these axes and settings, made as
  // build() makes it from its nodes and steps. nullopt for bytes no built grid has: a wrong count,
  // unknown bits, or a step that leaves the grid or touches a blocked node.
  static std::optional<CSpaceGrid> fromPackedNodes(const PerJoint<GridAxis>& axes, std::span<const std::uint8_t> nodes,
                                                   const RobotModel& model, int checked_steps);

  [[nodiscard]] int dimensions() const { return axes_.size(); }
  [[nodiscard]] const GridAxis& axis(int d) const { return axes_[d]; }
  [[nodiscard]] const PerJoint<GridAxis>& axes() const { return axes_; }
  [[nodiscard]] int cellCount() const { return cell_count_; }
  [[nodiscard]] int index(int cell, int d) const { return cell / stride_[d] % axes_[d].count; }
  [[nodiscard]] GridIndex indices(int cell) const {
    GridIndex out{};
    for (int d = 0; d < dimensions(); ++d) out[static_cast<size_t>(d)] = index(cell, d);
    return out;
  }
  [[nodiscard]] int cellAt(const GridIndex& idx) const {
    int c = 0;
    for (int d = 0; d < dimensions(); ++d) c += idx[static_cast<size_t>(d)] * stride_[d];
    return c;
  }
  [[nodiscard]] JointVector node(int cell) const {
    JointVector q(dimensions());
    for (int d = 0; d < dimensions(); ++d) q[d] = axes_[d].at(index(cell, d));
    return q;
  }
  [[nodiscard]] bool blocked(int cell) const { return blocked_[static_cast<size_t>(cell)] != 0; }
  // Every step to a neighbour, in the lexicographic order of their changes.
  [[nodiscard]] const std::vector<GridStep>& steps() const { return steps_table_; }
  // Whether the neighbour a step leads to from the node at `idx` lies in the grid.
  [[nodiscard]] bool inside(const GridIndex& idx, const GridStep& step) const {
    for (int d = 0; d < dimensions(); ++d) {
      const int a = idx[static_cast<size_t>(d)] + step.delta[static_cast<size_t>(d)];
      if (a < 0 || a >= axes_[d].count) return false;
    }
    return true;
  }
  // Whether step k of steps() from cell stays clear. The target must be inside the grid; blocked
  // ends make the step blocked.
  [[nodiscard]] bool stepFree(int cell, int k) const {
    const GridStep& step = steps_table_[static_cast<size_t>(k)];
    if (step.bit >= 0) return (node_steps_[static_cast<size_t>(cell)] >> step.bit) & 1U;
    const GridStep& back = steps_table_[static_cast<size_t>(step.reverse)];
    return (node_steps_[static_cast<size_t>(cell + step.cell_delta)] >> back.bit) & 1U;
  }
  // Weighted length of step k of steps().
  [[nodiscard]] double stepLength(int k) const { return step_length_[static_cast<size_t>(k)]; }
  // Calls visit(idx, cell) for every node whose indices lie in [lo, hi] (clamped to the grid), in
  // cell order.
  template <class Visit>
  void forEachInBox(GridIndex lo, GridIndex hi, Visit&& visit) const {
    for (int d = 0; d < dimensions(); ++d) {
      lo[static_cast<size_t>(d)] = std::max(0, lo[static_cast<size_t>(d)]);
      hi[static_cast<size_t>(d)] = std::min(axes_[d].count - 1, hi[static_cast<size_t>(d)]);
      if (lo[static_cast<size_t>(d)] > hi[static_cast<size_t>(d)]) return;
    }
    GridIndex idx = lo;
    while (true) {
      visit(static_cast<const GridIndex&>(idx), cellAt(idx));
      int d = dimensions() - 1;
      for (; d >= 0; --d) {
        if (++idx[static_cast<size_t>(d)] <= hi[static_cast<size_t>(d)]) break;
        idx[static_cast<size_t>(d)] = lo[static_cast<size_t>(d)];
      }
      if (d < 0) return;
    }
  }

  // Two-joint conveniences (the holes, and tests that draw a grid by hand).
  [[nodiscard]] const GridAxis& firstAxis() const { return axes_[0]; }
  [[nodiscard]] const GridAxis& secondAxis() const { return axes_[1]; }
  [[nodiscard]] int cell(int i_first, int i_second) const { return i_first * stride_[0] + i_second; }
  [[nodiscard]] int firstIndex(int cell) const { return index(cell, 0); }
  [[nodiscard]] int secondIndex(int cell) const { return index(cell, 1); }
  // Whether the step from cell by (di, dj), each in {-1, 0, 1}, not both 0, stays clear.
  [[nodiscard]] bool stepFree(int cell, int di, int dj) const { return stepFree(cell, stepIndex(di, dj)); }
  // Weighted length of a step of (di, dj) nodes.
  [[nodiscard]] double stepLength(int di, int dj) const { return stepLength(stepIndex(di, dj)); }
  // The index in steps() of the two-joint step (di, dj).
  static int stepIndex(int di, int dj) {
    const int lexicographic = (di + 1) * 3 + dj + 1;  // of the 3 x 3 offsets, (0, 0) at 4
    return lexicographic - (lexicographic > 4 ? 1 : 0);
  }

  // In [0, 1]: 1 on blocked nodes, falling to 0 at potential_range (weighted) from them.
  [[nodiscard]] double potential(int cell) const { return potential_[static_cast<size_t>(cell)]; }
  [[nodiscard]] const JointVector& metric() const { return metric_; }
  [[nodiscard]] double potentialWeight() const { return potential_weight_; }
  [[nodiscard]] double clearance_m() const { return clearance_m_; }
  // The holes of a two-joint grid, largest first.
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
  // The node with the largest indices <= q's (clamped to the grid).
  [[nodiscard]] int lowerCorner(const JointVector& q) const;

 private:
  void setAxes(const PerJoint<GridAxis>& axes);
  void computePotential(double range);
  void allowAllStepsBetweenFreeNodes();
  void findHoles();
  void labelRegions();

  PerJoint<GridAxis> axes_;
  std::array<int, kMaxJoints> stride_{};
  int cell_count_ = 0;
  std::vector<GridStep> steps_table_;  // see steps()
  std::vector<double> step_length_;    // per step of steps_table_
  std::vector<std::uint8_t> blocked_;
  std::vector<std::uint16_t> node_steps_;  // bit per forward step, see stepFree
  std::vector<float> potential_;
  std::vector<int> region_;  // see region()
  std::vector<GridHole> holes_;
  JointVector metric_;
  double potential_weight_ = 0.0;
  double clearance_m_ = 0.0;
  int checked_steps_ = 0;
};

}  // namespace cyber::planner

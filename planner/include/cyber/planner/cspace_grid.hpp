#pragma once
// The configuration-space grid of algorithm.md section 2.1: nodes over the joint box, the nodes
// where the robot is too close to an obstacle (blocked), and a potential that decays with the
// weighted distance from blocked nodes (a dynamic-programming distance transform).

#include <cstdint>
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
  // The fewest nodes with spacing <= max_step that cover [range.min, range.max].
  static GridAxis covering(const JointRange& range, double max_step);
};

class CSpaceGrid {
 public:
  CSpaceGrid() = default;
  // From a blocked mask (cell = i_elevator * arm.count + i_arm); computes the potential.
  CSpaceGrid(GridAxis elevator, GridAxis arm, std::vector<std::uint8_t> blocked, const JointVector& metric,
             const SearchSettings& search);

  // The grid of one collision world. A node is blocked when d(node) < clearance + inflation, with
  // inflation = (elevator step + reach * arm step) / 2: d is Lipschitz with constants (1, reach)
  // (CollisionWorld::lipschitzBound), and every point of a straight step between two adjacent
  // nodes lies within half a step per joint of one of them, so a step between free nodes keeps
  // d >= clearance everywhere, not only at the nodes.
  static CSpaceGrid build(const CollisionWorld& world, const RobotModel& model);

  [[nodiscard]] int cellCount() const { return elevator_.count * arm_.count; }
  [[nodiscard]] int cell(int i_elevator, int i_arm) const { return i_elevator * arm_.count + i_arm; }
  [[nodiscard]] int elevatorIndex(int cell) const { return cell / arm_.count; }
  [[nodiscard]] int armIndex(int cell) const { return cell % arm_.count; }
  [[nodiscard]] JointVector node(int cell) const {
    return JointVector(elevator_.at(elevatorIndex(cell)), arm_.at(armIndex(cell)));
  }
  [[nodiscard]] bool blocked(int cell) const { return blocked_[static_cast<size_t>(cell)] != 0; }
  // In [0, 1]: 1 on blocked nodes, falling to 0 at potential_range (weighted) from them.
  [[nodiscard]] double potential(int cell) const { return potential_[static_cast<size_t>(cell)]; }
  [[nodiscard]] const GridAxis& elevatorAxis() const { return elevator_; }
  [[nodiscard]] const GridAxis& armAxis() const { return arm_; }
  [[nodiscard]] const JointVector& metric() const { return metric_; }
  [[nodiscard]] double potentialWeight() const { return potential_weight_; }
  [[nodiscard]] double blockThreshold_m() const { return block_threshold_m_; }
  [[nodiscard]] int blockedCount() const;
  // Weighted length of a step of (di, dj) nodes.
  [[nodiscard]] double stepLength(int di, int dj) const;
  // The node with the largest indices <= q's (clamped to the grid).
  [[nodiscard]] int lowerCorner(const JointVector& q) const;

 private:
  void computePotential(double range);

  GridAxis elevator_;
  GridAxis arm_;
  std::vector<std::uint8_t> blocked_;
  std::vector<float> potential_;
  JointVector metric_ = JointVector(1.0, 1.0);
  double potential_weight_ = 0.0;
  double block_threshold_m_ = 0.0;
};

}  // namespace cyber::planner

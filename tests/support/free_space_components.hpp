#pragma once
// Connected components of an optimistic grid over a two-joint configuration space: a proof that a
// planner's "no path" is the right answer (docs/algorithm.md section 1: d is Lipschitz in q).

#include <vector>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/robot_model.hpp"

namespace cyber::test {

// Nodes at most `step` apart per joint (in the joint's own unit, m or rad) over the joint limits;
// a node is free when d >= clearance - L(h/2, h/2), L the world's Lipschitz bound. Any
// continuous path keeping the clearance passes within half a step per joint of a chain of
// 8-adjacent free nodes, so poses in different components cannot be joined by any such path.
class FreeSpaceComponents {
 public:
  FreeSpaceComponents(const planner::RobotModel& model, const planner::CollisionWorld& world, double step = 0.01);

  // The component of the node nearest q: a pose within the limits that keeps the clearance is
  // always on a free node (kBlocked otherwise).
  [[nodiscard]] int of(const planner::JointVector& q) const;
  [[nodiscard]] int count() const { return count_; }

  static constexpr int kBlocked = -2;

 private:
  [[nodiscard]] planner::JointVector node(int i, int j) const;
  [[nodiscard]] size_t index(int i, int j) const { return static_cast<size_t>(i * nj_ + j); }

  planner::JointRange range0_, range1_;
  double step0_ = 0.0, step1_ = 0.0;
  int ni_ = 0, nj_ = 0, count_ = 0;
  std::vector<int> label_;
};

}  // namespace cyber::test

#pragma once
// Whether two poses lie in different connected components of an optimistic grid over the
// configuration space of 1-3 joints: a proof that a planner's "no path" is the right answer
// (docs/algorithm.md section 1: d is Lipschitz in q).

#include <cstdint>
#include <vector>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/robot_model.hpp"

namespace cyber::test {

// Nodes over the joint limits, joint j's spaced at most step_m / rho_j (rho_j the world's point
// speed bound of joint j: no robot point moves more than step_m / 2 in half a step of one joint).
// A node is free when d >= clearance - L(h/2), L the world's Lipschitz bound: any continuous path
// keeping the clearance passes within half a step per joint of a chain of free nodes that are
// neighbours (any joints one step apart or equal: 3^N - 1 of them), so poses whose nodes no such
// chain joins cannot be joined by any such path. Nodes are judged only as a flood fill reaches
// them: from both poses at once, until one fill runs out (separated) or they meet (joined), so a
// pose in a small pocket is proven in the pocket's time however large the grid is.
class FreeSpaceComponents {
 public:
  enum class Verdict { kSeparated, kJoined, kBlocked, kTooFine };

  // kTooFine (and no grid) when the grid would have more than max_nodes nodes.
  FreeSpaceComponents(const planner::RobotModel& model, const planner::CollisionWorld& world, double step_m = 0.01,
                      int64_t max_nodes = int64_t{1} << 25);

  // kBlocked when the node nearest either pose is not free (a pose within the limits that keeps
  // the clearance never is).
  [[nodiscard]] Verdict separated(const planner::JointVector& a, const planner::JointVector& b);
  [[nodiscard]] int64_t nodeCount() const { return total_; }
  [[nodiscard]] bool tooFine() const { return too_fine_; }

 private:
  enum : uint8_t { kUnknown = 0, kBlockedNode = 1, kFree = 2 };
  [[nodiscard]] int64_t nodeOf(const planner::JointVector& q) const;
  [[nodiscard]] bool free(int64_t node);

  const planner::RobotModel& model_;
  const planner::CollisionWorld& world_;
  int n_ = 0;
  planner::JointVector min_, step_;
  int64_t count_[planner::kMaxJoints] = {1, 1, 1};
  int64_t stride_[planner::kMaxJoints] = {1, 1, 1};
  int64_t total_ = 0;
  bool too_fine_ = false;
  double slack_m_ = 0.0;
  std::vector<uint8_t> state_;    // kUnknown, kBlockedNode or kFree
  std::vector<uint8_t> visited_;  // 2 * query + side, of the query that reached the node
  uint8_t query_ = 0;
};

// Whether a grid of some step, coarsest first (0.02 to 0.0025 m of motion per joint step), proves
// a and b separated: a pocket a coarse grid's slack joins to the rest may need a finer one.
bool provedSeparated(const planner::RobotModel& model, const planner::CollisionWorld& world,
                     const planner::JointVector& a, const planner::JointVector& b);

}  // namespace cyber::test

#include "random_moves.hpp"

#include <algorithm>

#include "cyber/planner/collision_world.hpp"

namespace cyber::test {

using planner::CollisionWorld;
using planner::JointRange;
using planner::JointVector;
using planner::PlanRequest;

namespace {
constexpr int kPoseTries = 2000;
constexpr int kLegTries = 10;
}  // namespace

std::optional<PlanRequest> RandomMoveDraw::next(int move) {
  PlanRequest request;
  request.pieces = planner::HeldPieces::fromIndex(uniformInt(model_.pieceSetCount() - 1));
  if (move % kRandomOffsetEvery == 1) {
    const JointRange range = model_.scenes.front().offset_range_m;
    request.scene_offset_m = range.min + (range.max - range.min) * (1 + uniformInt(2)) / 3.0;
  }
  const CollisionWorld world(model_, model_.scenes.front(), request.pieces, request.scene_offset_m);
  const auto goal = clearPose(world);
  if (!goal) return std::nullopt;
  request.goal = *goal;
  const bool moving = move % kRandomMovingStartEvery == kRandomMovingStartEvery - 1;
  for (int leg = 0; leg < (moving ? kLegTries : 1); ++leg) {
    const auto start = clearPose(world);
    if (!start) return std::nullopt;
    request.start = *start;
    if (!moving) return request;
    // A moving start: the state at a random instant of a planned rest-to-rest move.
    PlanRequest ride = request;
    const auto end = clearPose(world);
    if (!end) return std::nullopt;
    ride.goal = *end;
    const auto planned = planner_.plan(ride);
    if (!planned.ok()) continue;
    const planner::Trajectory& trajectory = *planned.value().trajectory;
    const planner::TrajectorySample state = trajectory.sampleMotion(uniform(0.0, trajectory.duration_s()));
    request.start = state.q;
    request.start_velocity = state.qdot;
    return request;
  }
  return request;
}

std::optional<JointVector> RandomMoveDraw::clearPose(const CollisionWorld& world) {
  for (int tries = 0; tries < kPoseTries; ++tries) {
    JointVector q(model_.jointCount());
    if (uniformInt(1) == 0) {
      for (int j = 0; j < model_.jointCount(); ++j) q[j] = uniform(model_.range(j).min, model_.range(j).max);
    } else {
      // A named pose of any set, nudged by up to 3 % of each joint's range.
      const auto& sets = robot_.config.poses;
      const config::PoseSet& set = sets[static_cast<size_t>(uniformInt(static_cast<int>(sets.size()) - 1))];
      q = set.poses[static_cast<size_t>(uniformInt(static_cast<int>(set.poses.size()) - 1))].q;
      for (int j = 0; j < model_.jointCount(); ++j) {
        const JointRange r = model_.range(j);
        q[j] = std::clamp(q[j] + 0.03 * (r.max - r.min) * uniform(-1.0, 1.0), r.min, r.max);
      }
    }
    if (world.distance(q).value >= model_.clearance_m) return q;
  }
  return std::nullopt;
}

}  // namespace cyber::test

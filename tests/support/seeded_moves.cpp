#include "seeded_moves.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "cyber/planner/collision_world.hpp"

namespace cyber::test {

using planner::CollisionWorld;
using planner::JointRange;
using planner::JointVector;
using planner::PlanRequest;

PlanRequest SeededMoveDraw::next(int move) {
  PlanRequest request;
  request.pieces = planner::HeldPieces::fromIndex(uniformInt(model_.pieceSetCount() - 1));
  if (move % kSeededOffsetEvery == 1) {
    // Three offsets across the scene's range, so that a flood fill serves several refusals.
    const JointRange range = model_.scenes.front().offset_range_m;
    request.scene_offset_m = range.min + (range.max - range.min) * (1 + uniformInt(2)) / 3.0;
  }
  const CollisionWorld world(model_, model_.scenes.front(), request.pieces, request.scene_offset_m);
  request.goal = clearPose(world);
  if (move % kSeededMovingStartEvery != 3) {
    request.start = clearPose(world);
    return request;
  }
  // A moving start: the state at a random instant of a planned rest-to-rest move.
  for (;;) {
    PlanRequest leg = request;
    leg.start = clearPose(world);
    leg.goal = clearPose(world);
    const auto planned = robot_.planner.plan(leg);
    if (!planned.ok()) continue;
    const planner::Trajectory& trajectory = *planned.value().trajectory;
    const planner::TrajectorySample state =
        trajectory.sampleMotion(std::uniform_real_distribution<double>(0.0, trajectory.duration_s())(random_));
    request.start = state.q;
    request.start_velocity = state.qdot;
    return request;
  }
}

JointVector SeededMoveDraw::clearPose(const CollisionWorld& world) {
  for (;;) {
    JointVector q(model_.jointCount());
    if (uniformInt(1) == 0) {
      for (int j = 0; j < model_.jointCount(); ++j)
        q[j] = std::uniform_real_distribution<double>(model_.range(j).min, model_.range(j).max)(random_);
    } else {
      // A named pose of any set, nudged by up to 3 % of each joint's range.
      const config::PoseSet& set =
          robot_.config.poses[static_cast<size_t>(uniformInt(static_cast<int>(robot_.config.poses.size()) - 1))];
      q = set.poses[static_cast<size_t>(uniformInt(static_cast<int>(set.poses.size()) - 1))].q;
      for (int j = 0; j < model_.jointCount(); ++j) {
        const JointRange r = model_.range(j);
        q[j] = std::clamp(q[j] + 0.03 * (r.max - r.min) * std::uniform_real_distribution<double>(-1.0, 1.0)(random_),
                          r.min, r.max);
      }
    }
    if (world.distance(q).value >= model_.clearance_m) return q;
  }
}

std::string cyberPlanArguments(const PlanRequest& request) {
  // Each vector in chain order, as many values as the robot has joints.
  const auto values = [](const JointVector& q) {
    std::string text;
    for (Eigen::Index j = 0; j < q.size(); ++j) {
      char value[32];
      std::snprintf(value, sizeof value, "%s%.9g", j == 0 ? "" : ",", q[j]);
      text += value;
    }
    return text;
  };
  const JointVector velocity = request.start_velocity.size() == request.start.size()
                                   ? request.start_velocity
                                   : JointVector::Zero(request.start.size());
  return "--from=" + values(request.start) + " --to=" + values(request.goal) + " --from-velocity=" + values(velocity);
}

}  // namespace cyber::test

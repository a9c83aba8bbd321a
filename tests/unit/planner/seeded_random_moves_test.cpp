// Seeded random moves on each shipped robot, tried as a new user would: poses anywhere in the
// limits or near a named pose, any held set the config declares, a third with the scene shifted,
// a quarter moving starts (the state at a random instant of a planned move, to a new goal). Each
// plan is sound (limits, clearance at its offset, drive limits, columns that agree at 1 ms), and
// each refusal is a "no path" that a flood fill of the free space proves
// (free_space_components.hpp). Each plan is also within 2 % of the fastest ride along its own path
// (expectNearTheFastestRide, shipped_robots.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <tuple>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/motion_planner.hpp"
#include "free_space_components.hpp"
#include "shipped_robots.hpp"

namespace cyber::planner {
namespace {

constexpr int kMovesPerRobot = 50;
constexpr int kMovingStartEvery = 4;  // a quarter
constexpr int kOffsetEvery = 3;       // a third
constexpr double kMovingStartColumnsStepS = 1e-4;

// Draws the moves of one robot; a pose closer than the clearance to the scene at the move's
// offset is drawn again (the planner leaves those first: docs/algorithm.md section 5).
class MoveDraw {
 public:
  MoveDraw(const test::ShippedRobot& robot, unsigned seed) : robot_(robot), model_(robot.config.robot), random_(seed) {}

  PlanRequest next(int move) {
    PlanRequest request;
    request.pieces = HeldPieces::fromIndex(uniformInt(model_.pieceSetCount() - 1));
    if (move % kOffsetEvery == 1) {
      // Three offsets across the scene's range, so that a flood fill serves several refusals.
      const JointRange range = model_.scenes.front().offset_range_m;
      request.scene_offset_m = range.min + (range.max - range.min) * (1 + uniformInt(2)) / 3.0;
    }
    const CollisionWorld world(model_, model_.scenes.front(), request.pieces, request.scene_offset_m);
    request.goal = clearPose(world);
    if (move % kMovingStartEvery != 3) {
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
      const Trajectory& trajectory = *planned.value().trajectory;
      const TrajectorySample state =
          trajectory.sampleMotion(std::uniform_real_distribution<double>(0.0, trajectory.duration_s())(random_));
      request.start = state.q;
      request.start_velocity = state.qdot;
      return request;
    }
  }

 private:
  int uniformInt(int max) { return std::uniform_int_distribution<int>(0, max)(random_); }

  JointVector clearPose(const CollisionWorld& world) {
    for (;;) {
      JointVector q;
      if (uniformInt(1) == 0) {
        for (int j = 0; j < 2; ++j)
          q[j] = std::uniform_real_distribution<double>(model_.range(j).min, model_.range(j).max)(random_);
      } else {
        // A named pose of any set, nudged by up to 3 % of each joint's range.
        const config::PoseSet& set =
            robot_.config.poses[static_cast<size_t>(uniformInt(static_cast<int>(robot_.config.poses.size()) - 1))];
        q = set.poses[static_cast<size_t>(uniformInt(static_cast<int>(set.poses.size()) - 1))].q;
        for (int j = 0; j < 2; ++j) {
          const JointRange r = model_.range(j);
          q[j] = std::clamp(q[j] + 0.03 * (r.max - r.min) * std::uniform_real_distribution<double>(-1.0, 1.0)(random_),
                            r.min, r.max);
        }
      }
      if (world.distance(q).value >= model_.clearance_m) return q;
    }
  }

  const test::ShippedRobot& robot_;
  const RobotModel& model_;
  std::mt19937 random_;
};

// The move as cyber-plan's arguments, to reproduce it and hand it to the referee.
std::string cyberPlanArguments(const PlanRequest& request) {
  char text[200];
  std::snprintf(text, sizeof text, "--from=%.9g,%.9g --to=%.9g,%.9g --from-velocity=%.9g,%.9g", request.start[0],
                request.start[1], request.goal[0], request.goal[1], request.start_velocity[0],
                request.start_velocity[1]);
  return text;
}

class SeededRandomMoves : public ::testing::TestWithParam<const char*> {};

TEST_P(SeededRandomMoves, EveryPlanIsSoundAndEveryRefusalHasProvablyNoPath) {
  const test::ShippedRobot& robot = test::shippedRobot(GetParam());
  const RobotModel& model = robot.config.robot;
  std::map<std::tuple<int, double>, std::unique_ptr<test::FreeSpaceComponents>> components;
  MoveDraw draw(robot, 24);
  int planned = 0, refused = 0, moving = 0;
  double worst_ratio_from_rest = 0.0, worst_ratio_moving = 0.0;
  for (int move = 0; move < kMovesPerRobot; ++move) {
    const PlanRequest request = draw.next(move);
    const std::string label = std::string(GetParam()) + " move " + std::to_string(move) + " (" +
                              model.pieceSetName(request.pieces) + ", offset " +
                              std::to_string(request.scene_offset_m) + ", " + cyberPlanArguments(request) + ")";
    const auto plan = robot.planner.plan(request);
    if (plan.ok()) {
      const Trajectory& trajectory = *plan.value().trajectory;
      EXPECT_NEAR((trajectory.sampleMotion(0.0).q - request.start).norm(), 0.0, 1e-9) << label;
      EXPECT_NEAR((trajectory.sampleMotion(0.0).qdot - request.start_velocity).norm(), 0.0, 1e-6) << label;
      EXPECT_NEAR((trajectory.sampleMotion(trajectory.duration_s()).q - request.goal).norm(), 0.0, 1e-9) << label;
      // A moving start's columns agree at 1 ms when one of its candidates' do; otherwise the faster
      // is taken, whose columns still agree on finer samples (docs/moving-starts.md, "Consistent
      // columns"; cyber-plan --csv-step).
      const bool moving_start = !request.start_velocity.isZero();
      test::expectSound(model, trajectory, request.pieces, request.scene_offset_m, label,
                        moving_start ? kMovingStartColumnsStepS : 0.001);
      double& worst = moving_start ? worst_ratio_moving : worst_ratio_from_rest;
      worst = std::max(worst, test::expectNearTheFastestRide(trajectory, label));
      ++planned;
      moving += moving_start ? 1 : 0;
      continue;
    }
    ASSERT_EQ(plan.status(), PlanStatus::kNoPath) << label << ": " << plan.error().reason;
    auto& slot = components[{request.pieces.index(), request.scene_offset_m}];
    if (!slot) {
      const CollisionWorld world(model, model.scenes.front(), request.pieces, request.scene_offset_m);
      slot = std::make_unique<test::FreeSpaceComponents>(model, world);
    }
    EXPECT_NE(slot->of(request.start), test::FreeSpaceComponents::kBlocked) << label;
    EXPECT_NE(slot->of(request.start), slot->of(request.goal)) << label << ": refused, yet a path may exist";
    ++refused;
  }
  EXPECT_EQ(planned + refused, kMovesPerRobot);
  EXPECT_GT(moving, kMovesPerRobot / kMovingStartEvery / 2) << "moving starts are planned";
  RecordProperty("planned", planned);
  RecordProperty("refused", refused);
  RecordProperty("worst_ratio_to_ride_from_rest", std::to_string(worst_ratio_from_rest));
  RecordProperty("worst_ratio_to_ride_moving", std::to_string(worst_ratio_moving));
}

INSTANTIATE_TEST_SUITE_P(ShippedRobots, SeededRandomMoves, ::testing::ValuesIn(test::kShippedRobotNames),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace cyber::planner

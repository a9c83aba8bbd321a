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
#include <optional>
#include <random>
#include <string>
#include <tuple>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/motion_planner.hpp"
#include "free_space_components.hpp"
#include "joint_grid_components.hpp"
#include "seeded_moves.hpp"
#include "shipped_robots.hpp"

namespace cyber::planner {
namespace {

constexpr double kMovingStartColumnsStepS = 1e-4;

// The flood fill that proves a refusal: free_space_components.hpp's on two joints, the
// any-joint-count one (joint_grid_components.hpp) on the three-joint robot, on 2 cm / 20 mrad
// nodes there to keep its 3-D grid to a few million (a coarser grid is more optimistic, never
// wrong).
class FreeSpaceProof {
 public:
  FreeSpaceProof(const RobotModel& model, const CollisionWorld& world) {
    if (model.jointCount() == 2) {
      two_.emplace(model, world);
    } else {
      any_.emplace(model, world, 0.02);
    }
  }
  [[nodiscard]] int of(const JointVector& q) const { return two_ ? two_->of(q) : any_->of(q); }

 private:
  std::optional<test::FreeSpaceComponents> two_;
  std::optional<test::JointGridComponents> any_;
};

class SeededRandomMoves : public ::testing::TestWithParam<const char*> {};

TEST_P(SeededRandomMoves, EveryPlanIsSoundAndEveryRefusalHasProvablyNoPath) {
  const test::ShippedRobot& robot = test::shippedRobot(GetParam());
  const RobotModel& model = robot.config.robot;
  std::map<std::tuple<int, double>, std::unique_ptr<FreeSpaceProof>> components;
  test::SeededMoveDraw draw(robot, test::kSeededMovesSeed);
  int planned = 0, refused = 0, moving = 0;
  double worst_ratio_from_rest = 0.0, worst_ratio_moving = 0.0;
  for (int move = 0; move < test::kSeededMovesPerRobot; ++move) {
    const PlanRequest request = draw.next(move);
    const std::string label = std::string(GetParam()) + " move " + std::to_string(move) + " (" +
                              model.pieceSetName(request.pieces) + ", offset " +
                              std::to_string(request.scene_offset_m) + ", " + test::cyberPlanArguments(request) + ")";
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
    ASSERT_EQ(plan.status(), PlanStatus::kNoPath) << label << ": " << plan.error().message;
    auto& slot = components[{request.pieces.index(), request.scene_offset_m}];
    if (!slot) {
      const CollisionWorld world(model, model.scenes.front(), request.pieces, request.scene_offset_m);
      slot = std::make_unique<FreeSpaceProof>(model, world);
    }
    EXPECT_NE(slot->of(request.start), test::FreeSpaceComponents::kBlocked) << label;
    EXPECT_NE(slot->of(request.start), slot->of(request.goal)) << label << ": refused, yet a path may exist";
    ++refused;
  }
  EXPECT_EQ(planned + refused, test::kSeededMovesPerRobot);
  EXPECT_GT(moving, test::kSeededMovesPerRobot / test::kSeededMovingStartEvery / 2) << "moving starts are planned";
  RecordProperty("planned", planned);
  RecordProperty("refused", refused);
  RecordProperty("worst_ratio_to_ride_from_rest", std::to_string(worst_ratio_from_rest));
  RecordProperty("worst_ratio_to_ride_moving", std::to_string(worst_ratio_moving));
}

INSTANTIATE_TEST_SUITE_P(ShippedRobots, SeededRandomMoves, ::testing::ValuesIn(test::kShippedRobotNames),
                         test::shippedRobotParamName);

}  // namespace
}  // namespace cyber::planner

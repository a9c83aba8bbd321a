// Starts at rest inside the clearance that touch nothing (docs/algorithm.md section 5): the plan
// leaves along a line on which the distance never drops below the start's, reaches the clearance,
// keeps it from there to the goal, and its columns agree at 1 ms; a start that touches an obstacle is still refused.

#include "path/clearance_escape.hpp"

#include <random>

#include <gtest/gtest.h>

#include "cyber/planner/motion_planner.hpp"
#include "cyber/planner/trajectory.hpp"
#include "reference_model.hpp"

namespace cyber::planner {
namespace {

constexpr double kStepS = 0.001;
constexpr int kStarts = 60;
const JointVector kStow{{0.20, 1.57}};

// Seeded random poses of the bare arm whose distance to the nearest obstacle is between 10 % and
// 95 % of the clearance.
std::vector<JointVector> startsInsideTheClearance(const RobotModel& model, const CollisionWorld& world) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> t(model.range(0).min, model.range(0).max);
  std::uniform_real_distribution<double> theta(model.range(1).min, model.range(1).max);
  std::vector<JointVector> out;
  while (static_cast<int>(out.size()) < kStarts) {
    const JointVector q{{t(rng), theta(rng)}};
    const double d = world.distance(q).value;
    if (d > 0.1 * model.clearance_m && d < 0.95 * model.clearance_m) out.push_back(q);
  }
  return out;
}

TEST(ClearanceEscape, PlansFromInsideTheClearanceLeaveWithoutComingCloser) {
  const RobotModel& model = test::referenceModel();
  const auto planner = MotionPlanner::create(model);
  ASSERT_TRUE(planner.ok());
  const CollisionWorld world(model, model.scenes.front(), HeldPieces{});
  int planned = 0, inconsistent = 0;
  for (const JointVector& start : startsInsideTheClearance(model, world)) {
    SCOPED_TRACE(testing::Message() << "start " << start.transpose());
    PlanRequest request;
    request.start = start;
    request.goal = kStow;
    const Result<Plan> plan = planner.value().plan(request);
    if (!plan) {
      // Only a start with no straight way out may be refused, and then as a start in collision.
      EXPECT_EQ(plan.status(), PlanStatus::kStartInCollision) << plan.error().message;
      continue;
    }
    ++planned;
    const Trajectory& trajectory = *plan.value().trajectory;
    EXPECT_TRUE(plan.value().method.has(PlanMethod::kLeftTheClearance)) << plan.value().method.name();
    EXPECT_LT((trajectory.sample(0.0).q - start).norm(), 1e-12);
    EXPECT_LT((trajectory.sample(trajectory.duration_s()).q - kStow).norm(), 1e-9);
    const double d_start = world.distance(start).value;
    EXPECT_DOUBLE_EQ(plan.value().min_clearance_m, d_start);
    // Until the clearance is reached the distance only grows from the start's; after, it stays.
    bool cleared = false;
    const long steps = static_cast<long>(trajectory.duration_s() / kStepS);
    for (long i = 0; i <= steps; ++i) {
      const double d = world.distance(trajectory.sample(static_cast<double>(i) * kStepS).q).value;
      cleared = cleared || d >= model.clearance_m;
      EXPECT_GE(d, cleared ? model.clearance_m : d_start - 1e-9) << "t " << static_cast<double>(i) * kStepS;
    }
    EXPECT_TRUE(cleared);
    // The columns agree at 1 ms as the referee requires (2 % of the travel and the peak speed):
    // the short way out is slowed until they do.
    const ColumnConsistency columns = columnConsistency(trajectory, kStepS);
    EXPECT_LE(columns.position_error, 0.02);
    EXPECT_LE(columns.velocity_error, 0.02);
    inconsistent += columns.velocity_error > 0.02 || columns.position_error > 0.02 ? 1 : 0;
  }
  EXPECT_EQ(inconsistent, 0);
  // Nearly all such starts have a way out: 58 of these 60 (the count is fixed by the seed).
  EXPECT_GE(planned, 55);
}

TEST(ClearanceEscape, TheLineEndsBeyondTheClearanceAndIsTimedFromRestToRest) {
  const RobotModel& model = test::referenceModel();
  const CollisionWorld world(model, model.scenes.front(), HeldPieces{});
  ToppSolver solver(model.planner.topp);
  int escaped = 0;
  for (const JointVector& start : startsInsideTheClearance(model, world)) {
    const Result<Trajectory> escape = clearanceEscape(model, world, start, solver);
    if (!escape) continue;
    ++escaped;
    const TrajectorySample end = escape.value().sample(escape.value().duration_s());
    EXPECT_GE(world.distance(end.q).value, model.clearance_m + model.planner.escape.margin_m);
    EXPECT_LT(end.qdot.norm(), 1e-9);
    EXPECT_LT(escape.value().sample(0.0).qdot.norm(), 1e-12);
  }
  EXPECT_GT(escaped, 0);
}

TEST(ClearanceEscape, AStartTouchingAnObstacleIsStillRefused) {
  const RobotModel& model = test::referenceModel();
  const auto planner = MotionPlanner::create(model);
  ASSERT_TRUE(planner.ok());
  PlanRequest request;
  request.start = JointVector{{0.0, 4.71}};  // arm straight down at the bottom: through the drivetrain
  request.goal = kStow;
  const CollisionWorld world(model, model.scenes.front(), HeldPieces{});
  ASSERT_LT(world.distance(request.start).value, 0.0);
  const Result<Plan> plan = planner.value().plan(request);
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.status(), PlanStatus::kStartInCollision);
  EXPECT_NE(plan.error().message.find("touches an obstacle"), std::string::npos) << plan.error().message;
}

}  // namespace
}  // namespace cyber::planner

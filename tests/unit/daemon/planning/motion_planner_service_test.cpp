// The daemon's planning service over the real planner: what it streams is the planner's
// trajectory, with the feedforward never beyond the drive's voltage limit.

#include "cyber/daemon/motion_planner_service.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "cyber/planner.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"

namespace cyber::daemon {
namespace {

constexpr double kStepS = 0.001;  // the rate tools and the streamer sample at, or finer

const test::PublicMove& publicMove(const std::string& label) {
  for (const test::PublicMove& move : test::publicMoves()) {
    if (move.label == label) return move;
  }
  ADD_FAILURE() << "no public move " << label;
  return test::publicMoves().front();
}

// Moves whose optimised voltage passes the limit by a few millivolts at some 1 ms samples.
TEST(MotionPlannerService, FeedforwardStaysWithinTheVoltageLimitOtherwiseFollowsThePlan) {
  const planner::RobotModel& model = test::referenceModel();
  auto service = makeMotionPlannerService(model);
  ASSERT_TRUE(service.ok()) << service.error().message;
  auto planner = planner::MotionPlanner::create(model);
  ASSERT_TRUE(planner.ok());
  const double limits[2] = {model.drive(0).voltage_limit_volts, model.drive(1).voltage_limit_volts};
  int raw_beyond = 0;
  for (const char* label : {"none:L4->ALGAE_LOW", "none:PROCESSOR->L4", "coral:L1->NET"}) {
    SCOPED_TRACE(label);
    const test::PublicMove& move = publicMove(label);
    MotionRequest request;
    request.start = move.from;
    request.goal = move.to;
    request.pieces = move.pieces;
    const auto motion = service.value()->plan(request);
    ASSERT_TRUE(motion.ok()) << motion.error().message;
    planner::PlanRequest plan_request;
    plan_request.start = move.from;
    plan_request.goal = move.to;
    plan_request.pieces = move.pieces;
    const auto plan = planner.value().plan(plan_request);
    ASSERT_TRUE(plan.ok());
    const planner::Trajectory& trajectory = *plan.value().trajectory;
    const SetpointSource& source = *motion.value().trajectory;
    ASSERT_DOUBLE_EQ(source.durationS(), trajectory.duration_s());
    const long steps = static_cast<long>(std::ceil(trajectory.duration_s() / kStepS));
    for (long i = 0; i <= steps; ++i) {
      const double t = std::min(static_cast<double>(i) * kStepS, trajectory.duration_s());
      const JointSetpoints streamed = source.at(t);
      const planner::TrajectorySample planned = trajectory.sample(t);
      EXPECT_EQ(streamed.position, planned.q);
      EXPECT_EQ(streamed.velocity, planned.qdot);
      for (int j = 0; j < 2; ++j) {
        EXPECT_LE(std::abs(streamed.volts[j]), limits[j]) << "t " << t << " joint " << j;
        if (std::abs(planned.volts[j]) > limits[j]) {
          ++raw_beyond;
          EXPECT_EQ(std::abs(streamed.volts[j]), limits[j]);
        } else {
          EXPECT_EQ(streamed.volts[j], planned.volts[j]);
        }
      }
    }
  }
  // The moves do reach past the limit, so the clamp is what keeps the stream within it.
  EXPECT_GT(raw_beyond, 0);
}

// ARM_CANCEL's hold (docs/lcm.md, "Cancel and manual override"): a stop request is the planner's
// fastest stop from the moving state, in the world of the pieces held.
TEST(MotionPlannerService, AStopRequestIsThePlannersFastestStop) {
  const planner::RobotModel& model = test::referenceModel();
  auto service = makeMotionPlannerService(model);
  ASSERT_TRUE(service.ok()) << service.error().message;
  auto planner = planner::MotionPlanner::create(model);
  ASSERT_TRUE(planner.ok());
  const test::PublicMove& move = publicMove("coral:L1->NET");
  planner::PlanRequest plan_request;
  plan_request.start = move.from;
  plan_request.goal = move.to;
  plan_request.pieces = move.pieces;
  const auto plan = planner.value().plan(plan_request);
  ASSERT_TRUE(plan.ok());
  const planner::TrajectorySample moving = plan.value().trajectory->sample(0.3 * plan.value().trajectory->duration_s());
  ASSERT_GT(moving.qdot.norm(), 0.1);

  MotionRequest request;
  request.kind = MotionKind::kStop;
  request.start = moving.q;
  request.start_velocity = moving.qdot;
  request.goal = moving.q;
  request.pieces = move.pieces;
  const auto stop = service.value()->plan(request);
  ASSERT_TRUE(stop.ok()) << stop.error().message;
  const SetpointSource& source = *stop.value().trajectory;
  planner::PlanRequest stop_request;
  stop_request.start = moving.q;
  stop_request.start_velocity = moving.qdot;
  stop_request.pieces = move.pieces;
  const auto expected = planner.value().stop(stop_request);
  ASSERT_TRUE(expected.ok());
  EXPECT_DOUBLE_EQ(source.durationS(), expected.value().trajectory->duration_s());
  EXPECT_TRUE(source.at(0.0).position.isApprox(moving.q, 1e-9));
  EXPECT_TRUE(source.at(0.0).velocity.isApprox(moving.qdot, 1e-6));
  EXPECT_LT(source.at(source.durationS()).velocity.norm(), 1e-9);  // at rest (the streamer then holds, exactly 0)
  EXPECT_GT(stop.value().times_ms.total, 0.0);

  // At rest there is nothing to stop: the planner's own error, as a value.
  request.start_velocity = JointVector::Zero(2);
  EXPECT_EQ(service.value()->plan(request).status(), planner::PlanStatus::kInvalidInput);
  request.start_velocity = moving.qdot;
  request.scene = 7;
  EXPECT_EQ(service.value()->plan(request).status(), planner::PlanStatus::kInvalidInput);
}

}  // namespace
}  // namespace cyber::daemon

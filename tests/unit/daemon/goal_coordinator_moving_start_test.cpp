// A goal that arrives mid-motion never fails because of the motion: when planning from the moving
// start fails, the running motion is followed to its end and the goal planned from rest there
// (docs/moving-starts.md, "When the moving start fails").

#include <gtest/gtest.h>

#include "cyber/daemon/goal_coordinator.hpp"
#include "daemon_harness.hpp"

namespace cyber::daemon {
namespace {

using test::Harness;
using S = GoalStatus;

const JointVector kStow{{0.1, 1.2}};
const JointVector kHigh{{1.6, 2.8}};
const JointVector kLow{{0.4, 0.5}};

// The planner of these tests: `moving` answers a start with velocity, the harness's default plan
// one at rest unless `at_rest` fails too.
struct StartDependentPlanner {
  planner::PlanStatus moving = planner::PlanStatus::kInfeasibleStart;
  std::optional<planner::PlanStatus> at_rest;
};

void usePlanner(Harness& h, StartDependentPlanner p) {
  h.plan = [&h, p](const MotionRequest& request) {
    if (request.start_velocity.norm() > 0.0) {
      return planner::Result<PlannedMotion>::failure(p.moving, "the start velocity cannot be braked in time");
    }
    if (p.at_rest) return planner::Result<PlannedMotion>::failure(*p.at_rest, "blocked from rest too");
    return h.defaultPlan(request);
  };
}

bool noted(const Harness& h, const std::string& text) {
  for (const auto& note : h.sink.notes) {
    if (note.find(text) != std::string::npos) return true;
  }
  return false;
}

TEST(GoalCoordinatorMovingStart, AFailedMovingStartFinishesTheMotionAndPlansFromItsEnd) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh);
  h.run(0.3);  // inside the first motion
  ASSERT_EQ(h.lastRecord().mode, StreamMode::kMoving);
  usePlanner(h, {});
  h.goal(2, kLow);
  ASSERT_TRUE(h.runUntilFinal(2, 30.0));
  EXPECT_EQ(h.sink.last(2)->status, S::kDone);
  EXPECT_EQ(h.sink.last(1)->status, S::kDone);  // motion 1 ran to its end
  EXPECT_TRUE(noted(h, "finishing the running motion and planning from where it ends"));
  ASSERT_GE(h.sink.jobs_started.size(), 3u);
  EXPECT_GT(h.sink.jobs_started[1].request.start_velocity.norm(), 0.1);  // tried from the moving start first
  EXPECT_TRUE(h.sink.jobs_started.back().request.start.isApprox(kHigh));
  EXPECT_EQ(h.sink.jobs_started.back().request.start_velocity.norm(), 0.0);
  EXPECT_TRUE(h.lastRecord().setpoints.position.isApprox(kLow));
  EXPECT_EQ(h.coordinator().counters().plans_failed, 0);
}

TEST(GoalCoordinatorMovingStart, WhenRestFailsTooTheGoalFailsNamingBothReasons) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh);
  h.run(0.3);
  usePlanner(h, {planner::PlanStatus::kInfeasibleStart, planner::PlanStatus::kNoPath});
  h.goal(2, kLow);
  ASSERT_TRUE(h.runUntilFinal(2, 30.0));
  EXPECT_EQ(h.sink.last(2)->status, S::kFailed);
  EXPECT_EQ(h.sink.last(2)->reason,
            "no path: blocked from rest too (from the moving start: infeasible start: the start velocity cannot be "
            "braked in time)");
  ASSERT_TRUE(h.runUntilFinal(1, 30.0));
  EXPECT_EQ(h.sink.last(1)->status, S::kDone);  // the running motion still ends at rest
}

// The goal's own faults are not the motion's: rejected, no second plan.
TEST(GoalCoordinatorMovingStart, AGoalInCollisionIsRejectedWithoutPlanningAgain) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh);
  h.run(0.3);
  usePlanner(h, {planner::PlanStatus::kGoalInCollision, std::nullopt});
  h.goal(2, kLow);
  ASSERT_TRUE(h.runUntilFinal(2, 30.0));
  EXPECT_EQ(h.sink.last(2)->status, S::kRejected);
  EXPECT_EQ(h.sink.jobs_started.size(), 2u);
  EXPECT_FALSE(noted(h, "planning from where it ends"));
}

// A newer goal waiting when the moving start fails is planned instead; the failed one is cancelled.
TEST(GoalCoordinatorMovingStart, ANewerGoalWaitingSupersedesTheRetry) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh);
  h.run(0.3);
  usePlanner(h, {});
  h.setPlanTime(0.01);
  h.goal(2, kLow);
  h.goal(3, kStow);  // arrives while goal 2 is at the worker
  ASSERT_TRUE(h.runUntilFinal(3, 30.0));
  EXPECT_EQ(h.sink.last(2)->status, S::kCancelled);
  EXPECT_EQ(h.sink.last(2)->reason, "superseded by request 3");
  EXPECT_EQ(h.sink.last(3)->status, S::kDone);
}

}  // namespace
}  // namespace cyber::daemon

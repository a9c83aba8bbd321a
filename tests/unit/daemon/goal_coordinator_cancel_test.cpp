// ARM_CANCEL on the coordinator and the streamer together (fake clock, fake planner): a hold
// brakes the running motion to rest with a stop planned like a moving start; a release stops the
// setpoints until the next goal, which starts from the measured state (docs/lcm.md, "Cancel and
// manual override"; docs/design.md, "The life of a goal").
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <vector>

#include "cyber/daemon/goal_coordinator.hpp"
#include "daemon_harness.hpp"

namespace cyber::daemon {
namespace {

using test::Harness;
using S = GoalStatus;

const JointVector kStow{{0.1, 1.2}};
const JointVector kHigh{{1.6, 2.8}};
const JointVector kLow{{0.4, 0.5}};

const char* const kHoldReason = "cancelled by ARM_CANCEL: hold";
const char* const kReleaseReason = "cancelled by ARM_CANCEL: release (manual override)";

bool has(const std::vector<S>& statuses, S status) {
  return std::find(statuses.begin(), statuses.end(), status) != statuses.end();
}

// Steps until request `id` is executing (or 2 s pass).
bool runUntilExecuting(Harness& h, std::int64_t id) {
  for (int i = 0; i < 400 && !has(h.sink.of(id), S::kExecuting); ++i) h.step();
  return has(h.sink.of(id), S::kExecuting);
}

// The largest change of the position setpoint between two ticks from record `from` on.
double largestStep(const Harness& h, std::size_t from) {
  double largest = 0.0;
  for (std::size_t i = from + 1; i < h.records.size(); ++i) {
    largest = std::max(largest, (h.records[i].setpoints.position - h.records[i - 1].setpoints.position).norm());
  }
  return largest;
}

TEST(GoalCoordinatorCancel, HoldWhileExecutingSplicesAStopAndEndsAtRest) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh);
  ASSERT_TRUE(runUntilExecuting(h, 1));
  h.run(0.3);
  const double speed = h.lastRecord().setpoints.velocity.norm();
  ASSERT_GT(speed, 0.5);
  const std::size_t jobs = h.sink.jobs_started.size();
  const std::size_t at_cancel = h.records.size() - 1;

  h.cancel(1, CancelAction::kHold);
  EXPECT_EQ(h.sink.of(1), (std::vector<S>{S::kAccepted, S::kPlanning, S::kExecuting, S::kCancelled}));
  EXPECT_EQ(h.sink.last(1)->reason, kHoldReason);
  // The stop is planned like a moving start: from the commanded state a budget ahead.
  ASSERT_EQ(h.sink.jobs_started.size(), jobs + 1);
  const PlanJob stop = h.sink.jobs_started.back();
  EXPECT_EQ(stop.request.kind, MotionKind::kStop);
  EXPECT_EQ(stop.request_id, 1);  // it carries the request of the motion it brakes
  EXPECT_GT(stop.request.start_velocity.norm(), 0.5);

  h.run(0.5);
  EXPECT_EQ(h.coordinator().counters().stops_planned, 1);
  EXPECT_TRUE(h.sink.noted("ARM_CANCEL hold: request 1 brakes to rest in 200.0 ms"));
  EXPECT_EQ(h.coordinator().counters().goals_cancelled, 1);
  // Spliced like any plan (the streamer adopted it: its trajectory was published) and
  // continuous: no step larger than one period at the speed it had.
  ASSERT_EQ(h.sink.trajectories.size(), 2u);
  EXPECT_EQ(h.sink.trajectories[1].first, 1);
  EXPECT_LT(largestStep(h, at_cancel), speed * 0.005 * 1.5);
  // At rest where the stop ends, short of the cancelled target, holding with zero velocity.
  const auto& r = h.lastRecord();
  EXPECT_EQ(r.mode, StreamMode::kHolding);
  EXPECT_EQ(r.setpoints.velocity, JointVector::Zero(2));
  EXPECT_TRUE(
      r.setpoints.position.isApprox(stop.request.start + 0.5 * h.stop_duration_s * stop.request.start_velocity, 1e-9));
  EXPECT_GT((r.setpoints.position - kHigh).norm(), 0.3);
  // Nothing more is said about the cancelled goal (no DONE when its stop ends).
  EXPECT_EQ(h.sink.of(1).size(), 4u);
  EXPECT_TRUE(h.coordinator().idle());
}

TEST(GoalCoordinatorCancel, HoldWhilePlanningDropsThePlanWhenItReturnsAndBrakes) {
  Harness h(false, 0.02);  // plans take 20 ms
  h.start(kStow);
  h.goal(1, kHigh);
  ASSERT_TRUE(runUntilExecuting(h, 1));
  h.run(0.2);
  h.goal(2, kLow);  // planned from the running motion
  ASSERT_TRUE(h.sink.job.has_value());
  ASSERT_EQ(h.sink.job->request_id, 2);

  h.cancel(CancelRequest::kActive, CancelAction::kHold);
  for (std::int64_t id : {1, 2}) {
    EXPECT_EQ(h.sink.last(id)->status, S::kCancelled) << id;
    EXPECT_EQ(h.sink.last(id)->reason, kHoldReason) << id;
  }
  h.run(0.6);
  // 2's plan came back and was not posted; the stop was planned after it.
  for (const auto& [id, start] : h.sink.trajectories) EXPECT_NE(id, 2);
  EXPECT_TRUE(h.sink.noted("request 2: plan dropped (cancelled by ARM_CANCEL)"));
  EXPECT_EQ(h.sink.jobs_started.back().request.kind, MotionKind::kStop);
  EXPECT_EQ(h.coordinator().counters().stops_planned, 1);
  const auto& r = h.lastRecord();
  EXPECT_EQ(r.setpoints.velocity, JointVector::Zero(2));
  EXPECT_GT((r.setpoints.position - kHigh).norm(), 0.3);
  EXPECT_GT((r.setpoints.position - kLow).norm(), 0.3);
  EXPECT_EQ(h.sink.of(2), (std::vector<S>{S::kAccepted, S::kPlanning, S::kCancelled}));
}

TEST(GoalCoordinatorCancel, HoldAtRestJustHolds) {
  Harness h(false, 0.02);
  h.start(kStow);
  h.goal(1, kHigh);  // planned from rest
  h.step();
  h.cancel(1, CancelAction::kHold);
  EXPECT_EQ(h.sink.of(1), (std::vector<S>{S::kAccepted, S::kPlanning, S::kCancelled}));
  h.run(0.3);
  // Its plan is dropped, and at rest there is nothing to brake: no stop is planned.
  EXPECT_EQ(h.sink.jobs_started.size(), 1u);
  EXPECT_TRUE(h.sink.trajectories.empty());
  EXPECT_EQ(h.coordinator().counters().stops_planned, 0);
  EXPECT_TRUE(h.sink.noted("at rest; holding there"));
  for (const auto& r : h.records) {
    EXPECT_TRUE(r.sent);
    EXPECT_EQ(r.mode, StreamMode::kHolding);
    EXPECT_EQ(r.setpoints.position, kStow);
  }
  EXPECT_TRUE(h.coordinator().idle());
}

TEST(GoalCoordinatorCancel, ACancelNamingNoOpenGoalChangesNothing) {
  Harness h;
  h.start(kStow);
  h.goal(1, kLow);
  ASSERT_TRUE(h.runUntilFinal(1));
  ASSERT_EQ(h.sink.last(1)->status, S::kDone);
  h.goal(2, kHigh);
  ASSERT_TRUE(runUntilExecuting(h, 2));
  const std::size_t statuses = h.sink.statuses.size();
  const std::size_t jobs = h.sink.jobs_started.size();

  // A robot command's end() after its move was done, and ids never sent.
  h.cancel(1, CancelAction::kHold);
  h.cancel(1, CancelAction::kRelease);
  h.cancel(77, CancelAction::kHold);
  EXPECT_EQ(h.sink.statuses.size(), statuses);
  EXPECT_EQ(h.sink.jobs_started.size(), jobs);
  EXPECT_FALSE(h.coordinator().released());
  EXPECT_EQ(h.sink.release_generation, 0u);
  EXPECT_TRUE(h.sink.noted("ARM_CANCEL hold for request 1 ignored: no such open goal"));
  EXPECT_TRUE(h.sink.noted("ARM_CANCEL release for request 1 ignored: no such open goal"));
  ASSERT_TRUE(h.runUntilFinal(2));
  EXPECT_EQ(h.sink.of(2), (std::vector<S>{S::kAccepted, S::kPlanning, S::kExecuting, S::kDone}));

  // Nothing open: a hold of "whatever is active" changes nothing either.
  h.cancel(CancelRequest::kActive, CancelAction::kHold);
  EXPECT_EQ(h.sink.jobs_started.size(), jobs);
}

TEST(GoalCoordinatorCancel, WithoutAnAdmissibleStopTheRunningMotionRunsToItsEnd) {
  Harness h;
  h.plan = [&h](const MotionRequest& request) {
    if (request.kind == MotionKind::kStop) {
      return planner::Result<PlannedMotion>::failure(planner::PlanStatus::kClearanceNotMet,
                                                     "the braking segment comes 0.01 m from l2_branch");
    }
    return h.defaultPlan(request);
  };
  h.start(kStow);
  h.goal(1, kHigh);
  ASSERT_TRUE(runUntilExecuting(h, 1));
  h.run(0.2);
  h.cancel(1, CancelAction::kHold);
  EXPECT_EQ(h.sink.last(1)->status, S::kCancelled);
  h.run(2.0);
  EXPECT_TRUE(h.sink.noted("no admissible stop for request 1"));
  EXPECT_TRUE(h.sink.noted("the running motion continues to its end at rest"));
  // The motion (collision-free) ended where it was going, at rest; no further status for 1.
  const auto& r = h.lastRecord();
  EXPECT_TRUE(r.setpoints.position.isApprox(kHigh, 1e-9));
  EXPECT_EQ(r.setpoints.velocity, JointVector::Zero(2));
  EXPECT_EQ(h.sink.of(1).size(), 4u);
}

// Steps with the mechanism measured at `measured` (the robot program moves it while released).
void runMeasured(Harness& h, const JointVector& measured, double seconds) {
  const MonoNs end = h.now + secondsToNs(seconds);
  while (h.now < end) {
    h.feedState(measured);
    h.step();
  }
}

TEST(GoalCoordinatorCancel, ReleaseStopsTheSetpointsAndTheNextGoalStartsFromTheMeasuredState) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh);
  ASSERT_TRUE(runUntilExecuting(h, 1));
  h.run(0.2);
  h.auto_state = false;

  h.cancel(CancelRequest::kActive, CancelAction::kRelease);
  EXPECT_EQ(h.sink.last(1)->status, S::kCancelled);
  EXPECT_EQ(h.sink.last(1)->reason, kReleaseReason);
  EXPECT_TRUE(h.coordinator().released());
  const std::size_t released_from = h.records.size();
  // The robot program drives the joints to kLow: no setpoint is streamed meanwhile.
  runMeasured(h, kLow, 0.5);
  for (std::size_t i = released_from; i < h.records.size(); ++i) {
    EXPECT_FALSE(h.records[i].sent) << i;
    EXPECT_EQ(h.records[i].mode, StreamMode::kReleased) << i;
  }
  EXPECT_EQ(h.coordinator().counters().stops_planned, 0);

  // The next goal ends the release: the streamer holds where the mechanism is, and the plan starts there.
  const std::size_t jobs = h.sink.jobs_started.size();
  h.goal(2, kHigh);
  EXPECT_FALSE(h.coordinator().released());
  EXPECT_EQ(h.sink.of(2), std::vector<S>{S::kAccepted});
  runMeasured(h, kLow, 0.02);
  ASSERT_EQ(h.sink.jobs_started.size(), jobs + 1);
  EXPECT_EQ(h.sink.jobs_started.back().request.start, kLow);
  EXPECT_EQ(h.sink.jobs_started.back().request.start_velocity, JointVector::Zero(2));
  h.auto_state = true;
  ASSERT_TRUE(h.runUntilFinal(2));
  EXPECT_EQ(h.sink.of(2), (std::vector<S>{S::kAccepted, S::kPlanning, S::kExecuting, S::kDone}));
  h.run(0.05);
  EXPECT_TRUE(h.lastRecord().setpoints.position.isApprox(kHigh, 1e-9));
  EXPECT_EQ(h.lastRecord().mode, StreamMode::kHolding);
}

TEST(GoalCoordinatorCancel, AReleaseEndedBeforeAnyTickStillRestartsFromTheMeasuredState) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh);
  ASSERT_TRUE(runUntilExecuting(h, 1));
  h.run(0.2);
  h.auto_state = false;
  h.feedState(kLow);
  h.cancel(CancelRequest::kActive, CancelAction::kRelease);
  h.goal(2, kHigh);  // within the same stream period
  h.step();
  EXPECT_FALSE(h.lastRecord().sent);
  EXPECT_EQ(h.lastRecord().mode, StreamMode::kReleased);
  h.feedState(kLow);
  h.step();
  EXPECT_TRUE(h.lastRecord().sent);
  EXPECT_EQ(h.lastRecord().setpoints.position, kLow);
  EXPECT_EQ(h.sink.jobs_started.back().request.start, kLow);
  EXPECT_EQ(h.sink.last(2)->status, S::kPlanning);
}

TEST(GoalCoordinatorCancel, AReleaseWithNothingOpenReleasesAndOnlyAValidGoalEndsIt) {
  Harness h;
  h.start(kStow);
  h.cancel(CancelRequest::kActive, CancelAction::kRelease);
  EXPECT_TRUE(h.coordinator().released());
  EXPECT_EQ(h.sink.release_generation, 1u);
  h.run(0.05);
  EXPECT_FALSE(h.lastRecord().sent);
  EXPECT_EQ(h.lastRecord().mode, StreamMode::kReleased);
  // Neither a hold nor a second release nor a rejected goal ends it.
  h.cancel(CancelRequest::kActive, CancelAction::kHold);
  h.cancel(CancelRequest::kActive, CancelAction::kRelease);
  EXPECT_TRUE(h.sink.noted("already released"));
  h.goal(3, JointVector{{5.0, 1.0}});  // out of range
  EXPECT_EQ(h.sink.of(3), std::vector<S>{S::kRejected});
  h.run(0.05);
  EXPECT_TRUE(h.coordinator().released());
  EXPECT_FALSE(h.lastRecord().sent);
  EXPECT_EQ(h.sink.release_generation, 1u);
  h.goal(4, kHigh);
  EXPECT_EQ(h.sink.release_generation, 2u);
  ASSERT_TRUE(h.runUntilFinal(4));
  EXPECT_EQ(h.sink.last(4)->status, S::kDone);
}

}  // namespace
}  // namespace cyber::daemon

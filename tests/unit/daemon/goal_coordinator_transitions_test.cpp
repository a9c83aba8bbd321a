// Every transition of the coordinator's state machine (docs/design.md, "The life of a goal"),
// driven by hand-made plan results and stream events, and the events each state ignores.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cyber/daemon/goal_coordinator.hpp"
#include "daemon_harness.hpp"

namespace cyber::daemon {
namespace {

using S = GoalStatus;

const JointVector kStow{{0.1, 1.2}};
const JointVector kHigh{{1.6, 2.8}};
const JointVector kLow{{0.4, 0.5}};

constexpr MonoNs kMs = 1'000'000;

class Transitions : public ::testing::Test {
 protected:
  Transitions() : coordinator(robot, settings(), sink) { sink.clock = &now; }

  static CoordinatorSettings settings() {
    CoordinatorSettings s;
    s.planning_budget_s = 0.03;
    s.stream_period_s = 0.005;
    return s;
  }

  void goal(std::int64_t id, const JointVector& q, GateReason gate = GateReason::kOpen) {
    coordinator.onGoal(test::Harness::request(id, q), now, GateVerdict{gate});
  }
  StreamEvent event(StreamEventKind kind) const {
    StreamEvent e;
    e.kind = kind;
    e.time_ns = now;
    e.epoch = epoch;
    return e;
  }
  // kHolding and kStopped start a new epoch at q.
  StreamEvent newEpoch(StreamEventKind kind, const JointVector& q) {
    StreamEvent e = event(kind);
    e.epoch = ++epoch;
    e.position = q;
    e.release_generation = generation;
    return e;
  }
  void hold(const JointVector& q, HoldCause cause = HoldCause::kEnabled) {
    StreamEvent e = newEpoch(StreamEventKind::kHolding, q);
    e.hold_cause = cause;
    coordinator.onStreamEvent(e, now);
  }
  void stopped(GateReason reason) {
    StreamEvent e = newEpoch(StreamEventKind::kStopped, kStow);
    e.gate_reason = reason;
    coordinator.onStreamEvent(e, now);
  }
  // The worker's answer to the job it holds: a motion of `duration_s` to the job's goal.
  void planned(double duration_s = 1.0) {
    ASSERT_TRUE(sink.job.has_value());
    const PlanJob job = *sink.job;
    sink.job.reset();
    PlannedMotion motion;
    motion.trajectory =
        test::makeHermite(job.request.start, job.request.start_velocity, job.request.goal, duration_s, robot);
    coordinator.onPlanResult(job.job_id, planner::Result<PlannedMotion>(motion), 0.001, now);
  }
  void failed(planner::PlanStatus status) {
    ASSERT_TRUE(sink.job.has_value());
    const PlanJob job = *sink.job;
    sink.job.reset();
    coordinator.onPlanResult(job.job_id, planner::Result<PlannedMotion>::failure(status, "why"), 0.001, now);
  }
  // The streamer takes the posted program, as Streamer::consider does.
  void adopt() {
    ASSERT_NE(sink.program, nullptr);
    Program taken = *sink.program;
    sink.program.reset();
    taken.resolveFloatingStart(now);
    StreamEvent e = event(StreamEventKind::kAdopted);
    e.program_id = taken.id;
    e.start_ns = taken.splice_ns;
    coordinator.onStreamEvent(e, now);
  }
  void rejectPosted(RejectReason reason) {
    ASSERT_NE(sink.program, nullptr);
    StreamEvent e = event(StreamEventKind::kRejected);
    e.program_id = sink.program->id;
    e.reject_reason = reason;
    sink.program.reset();
    coordinator.onStreamEvent(e, now);
  }
  void streamed(StreamEventKind kind, std::int64_t request_id) {
    StreamEvent e = event(kind);
    e.request_id = request_id;
    coordinator.onStreamEvent(e, now);
  }
  std::vector<S> statuses(std::int64_t id) const { return sink.of(id); }
  std::string reason(std::int64_t id) const { return sink.last(id)->reason; }

  const planner::RobotModel& robot = cyber::test::referenceModel();
  test::RecordingSink sink;
  MonoNs now = 1'000 * kMs;
  std::uint64_t epoch = 0;
  std::uint32_t generation = 0;  // the release generation the streamer has seen (its events carry it)
  GoalCoordinator coordinator;
};

// Stream region.

TEST_F(Transitions, StoppedAtStartAGoalIsAcceptedAndWaitsForTheFirstHold) {
  goal(1, kHigh);
  EXPECT_EQ(statuses(1), std::vector<S>{S::kAccepted});
  EXPECT_TRUE(sink.jobs_started.empty());
  EXPECT_FALSE(coordinator.idle());
  hold(kStow);  // Stopped -> Streaming
  ASSERT_EQ(sink.jobs_started.size(), 1u);
  EXPECT_EQ(sink.jobs_started[0].request.start, kStow);
  EXPECT_EQ(statuses(1), (std::vector<S>{S::kAccepted, S::kPlanning}));
}

TEST_F(Transitions, StreamingToStoppedCancelsTheScheduledTheExecutingAndTheWaitingGoal) {
  hold(kStow);
  goal(1, kHigh);
  planned(10.0);
  adopt();
  streamed(StreamEventKind::kExecuting, 1);
  goal(2, kLow);   // planning
  goal(3, kStow);  // waiting
  stopped(GateReason::kRobotDisabled);
  for (std::int64_t id : {1, 3}) {
    EXPECT_EQ(sink.last(id)->status, S::kCancelled) << id;
    EXPECT_EQ(reason(id), "motion stopped: " + std::string(toString(GateReason::kRobotDisabled))) << id;
  }
  EXPECT_EQ(coordinator.mirror().segmentCount(), 0);
  // The plan in progress comes back to a stopped stream: cancelled, nothing posted.
  planned();
  EXPECT_EQ(sink.last(2)->status, S::kCancelled);
  EXPECT_EQ(reason(2), "motion stopped while planning: " + std::string(toString(GateReason::kRobotDisabled)));
  EXPECT_EQ(sink.program, nullptr);
  EXPECT_TRUE(coordinator.idle());
}

TEST_F(Transitions, StoppedToStoppedKeepsTheLatestReason) {
  hold(kStow);
  goal(1, kHigh);
  stopped(GateReason::kNoHeartbeat);
  stopped(GateReason::kBroadcastDisable);
  planned();
  EXPECT_EQ(reason(1), "motion stopped while planning: " + std::string(toString(GateReason::kBroadcastDisable)));
}

TEST_F(Transitions, AGoalAcceptedWhileStoppedIsPlannedWhenTheStreamHoldsAgain) {
  hold(kStow);
  stopped(GateReason::kStateStale);
  goal(1, kHigh);  // the event loop's gate may open a tick before the streamer's
  EXPECT_TRUE(sink.jobs_started.empty());
  hold(kLow);  // Stopped -> Streaming, holding where the mechanism is
  ASSERT_EQ(sink.jobs_started.size(), 1u);
  EXPECT_EQ(sink.jobs_started[0].request.start, kLow);
}

TEST_F(Transitions, StreamingToStreamingOnANewHoldReplansThePlanInProgress) {
  hold(kStow);
  goal(1, kHigh);
  hold(kLow);  // a new epoch while planning: the plan's base is gone
  planned();
  EXPECT_EQ(sink.program, nullptr);
  ASSERT_EQ(sink.jobs_started.size(), 2u);
  EXPECT_EQ(sink.jobs_started[1].request.start, kLow);
  EXPECT_EQ(statuses(1), (std::vector<S>{S::kAccepted, S::kPlanning}));  // PLANNING once
  EXPECT_NE(sink.notes.back().find("the running motion changed while planning"), std::string::npos);
}

TEST_F(Transitions, ShutDownCancelsEveryOpenGoalAndIsTerminal) {
  hold(kStow);
  goal(1, kHigh);
  planned(10.0);
  adopt();
  goal(2, kLow);   // planning
  goal(3, kStow);  // waiting
  coordinator.onShutdown(now);
  for (std::int64_t id : {1, 2, 3}) {
    EXPECT_EQ(sink.last(id)->status, S::kCancelled) << id;
    EXPECT_EQ(reason(id), "daemon shutting down") << id;
  }
  // The plan in progress comes back: nothing is posted or re-planned.
  const std::size_t jobs = sink.jobs_started.size();
  planned();
  EXPECT_EQ(sink.program, nullptr);
  EXPECT_EQ(sink.jobs_started.size(), jobs);
  EXPECT_TRUE(coordinator.idle());
  // Neither the shutdown hold, a stop nor a new hold leaves ShutDown.
  hold(kStow, HoldCause::kShutdown);
  stopped(GateReason::kNoState);
  hold(kStow);
  goal(4, kHigh);
  EXPECT_EQ(statuses(4), std::vector<S>{S::kRejected});
  EXPECT_EQ(reason(4), "daemon shutting down");
  EXPECT_EQ(sink.jobs_started.size(), jobs);
}

TEST_F(Transitions, AProgramPostedBeforeShutdownAndRejectedIsNotReplanned) {
  hold(kStow);
  goal(1, kHigh);
  planned();
  coordinator.onShutdown(now);
  rejectPosted(RejectReason::kStaleBase);
  EXPECT_EQ(sink.jobs_started.size(), 1u);
  EXPECT_TRUE(coordinator.idle());
  EXPECT_EQ(statuses(1), (std::vector<S>{S::kAccepted, S::kPlanning, S::kCancelled}));
}

TEST_F(Transitions, TheShutdownHoldCancelsTheScheduledGoals) {
  hold(kStow);
  goal(1, kHigh);
  planned(10.0);
  adopt();
  hold(kStow, HoldCause::kShutdown);
  EXPECT_EQ(sink.last(1)->status, S::kCancelled);
  EXPECT_EQ(reason(1), "daemon shutting down");
}

// Pipeline region.

TEST_F(Transitions, IdlePlanningPostedIdle) {
  hold(kStow);
  EXPECT_TRUE(coordinator.idle());
  goal(1, kHigh);  // Idle -> Planning
  EXPECT_FALSE(coordinator.idle());
  ASSERT_TRUE(sink.job.has_value());
  EXPECT_EQ(sink.job->request_id, 1);
  planned();  // Planning -> Posted
  ASSERT_NE(sink.program, nullptr);
  EXPECT_FALSE(coordinator.idle());
  adopt();  // Posted -> Idle
  EXPECT_TRUE(coordinator.idle());
  EXPECT_EQ(coordinator.mirror().segmentCount(), 1);
  ASSERT_EQ(sink.trajectories.size(), 1u);
  EXPECT_EQ(sink.trajectories[0], std::make_pair(std::int64_t{1}, now));
  streamed(StreamEventKind::kExecuting, 1);
  streamed(StreamEventKind::kDone, 1);
  EXPECT_EQ(statuses(1), (std::vector<S>{S::kAccepted, S::kPlanning, S::kExecuting, S::kDone}));
}

TEST_F(Transitions, PlanningToIdleOnAPlannerErrorAnswersRejectedOrFailed) {
  hold(kStow);
  goal(1, kHigh);
  failed(planner::PlanStatus::kGoalInCollision);
  EXPECT_EQ(sink.last(1)->status, S::kRejected);
  goal(2, kHigh);
  failed(planner::PlanStatus::kNoPath);
  EXPECT_EQ(sink.last(2)->status, S::kFailed);
  EXPECT_TRUE(coordinator.idle());
}

TEST_F(Transitions, PlanningToIdleOnAResultWithoutTrajectoryFails) {
  hold(kStow);
  goal(1, kHigh);
  const PlanJob job = *sink.job;
  coordinator.onPlanResult(job.job_id, planner::Result<PlannedMotion>(PlannedMotion{}), 0.001, now);
  EXPECT_EQ(sink.last(1)->status, S::kFailed);
  EXPECT_EQ(reason(1), "internal error: the planner returned no trajectory");
  EXPECT_EQ(sink.program, nullptr);
  EXPECT_TRUE(coordinator.idle());
}

TEST_F(Transitions, AFailedPlanStartsTheGoalWaitingBehindIt) {
  hold(kStow);
  goal(1, kHigh);
  goal(2, kLow);
  failed(planner::PlanStatus::kNoPath);
  ASSERT_EQ(sink.jobs_started.size(), 2u);
  EXPECT_EQ(sink.jobs_started[1].request_id, 2);
}

TEST_F(Transitions, PlanningToIdleOnALatePlanReplansFromALaterPoint) {
  hold(kStow);
  goal(1, kHigh);
  planned(10.0);
  adopt();
  goal(2, kLow);  // a splice 30 ms ahead
  now += 40 * kMs;
  planned();
  EXPECT_EQ(sink.program, nullptr);
  EXPECT_EQ(coordinator.counters().plans_late, 1);
  ASSERT_EQ(sink.jobs_started.size(), 3u);
  EXPECT_EQ(sink.jobs_started[2].request_id, 2);
  EXPECT_GT(sink.jobs_started[2].request.start_velocity.norm(), 0.0);
}

TEST_F(Transitions, AReplanWithANewerGoalWaitingIsSupersededInstead) {
  hold(kStow);
  goal(1, kHigh);
  hold(kLow);
  goal(2, kStow);  // waits behind 1
  planned();       // 1's base is gone: it would be re-planned, but 2 is newer
  EXPECT_EQ(sink.last(1)->status, S::kCancelled);
  EXPECT_EQ(reason(1), "superseded by request 2");
  EXPECT_EQ(sink.jobs_started.size(), 1u);  // 2 starts on the next event or timer
  coordinator.onTimer(now);
  ASSERT_EQ(sink.jobs_started.size(), 2u);
  EXPECT_EQ(sink.jobs_started[1].request_id, 2);
}

TEST_F(Transitions, PostedToIdleOnRejectionReplansAndCountsOnlyLateOnes) {
  hold(kStow);
  goal(1, kHigh);
  planned();
  rejectPosted(RejectReason::kStaleBase);
  EXPECT_EQ(coordinator.counters().plans_late, 0);
  ASSERT_EQ(sink.jobs_started.size(), 2u);
  planned();
  rejectPosted(RejectReason::kLate);
  EXPECT_EQ(coordinator.counters().plans_late, 1);
  ASSERT_EQ(sink.jobs_started.size(), 3u);
  EXPECT_NE(sink.notes.back().find("the streamer did not take the plan (late"), std::string::npos) << sink.notes.back();
  EXPECT_EQ(statuses(1), (std::vector<S>{S::kAccepted, S::kPlanning}));
}

TEST_F(Transitions, LateRejectionsFallBackToPlanningFromWhereTheMotionEnds) {
  hold(kStow);
  goal(1, kHigh);
  planned(10.0);
  adopt();
  goal(2, kLow);
  for (int attempt = 0; attempt < 3; ++attempt) {
    ASSERT_FALSE(sink.jobs_started.back().request.start.isApprox(kHigh)) << attempt;
    planned();
    rejectPosted(RejectReason::kLate);
  }
  EXPECT_TRUE(sink.jobs_started.back().request.start.isApprox(kHigh));  // from rest at 1's end
  EXPECT_EQ(sink.jobs_started.back().request.start_velocity, JointVector::Zero(2));
  planned();
  adopt();
  ASSERT_EQ(coordinator.mirror().segmentCount(), 2);
  EXPECT_EQ(coordinator.mirror().segment(1).start_ns, coordinator.mirror().segment(0).start_ns + secondsToNs(10.0));
}

TEST_F(Transitions, ARejectionAfterTheStreamStoppedIsNotReplanned) {
  hold(kStow);
  goal(1, kHigh);
  planned();
  stopped(GateReason::kNoHeartbeat);
  EXPECT_EQ(reason(1), "motion stopped: " + std::string(toString(GateReason::kNoHeartbeat)));
  rejectPosted(RejectReason::kStaleBase);
  EXPECT_EQ(sink.jobs_started.size(), 1u);
  EXPECT_TRUE(coordinator.idle());
}

TEST_F(Transitions, AdoptionCancelsTheGoalsWhoseSegmentsItReplaced) {
  hold(kStow);
  goal(1, kHigh);
  planned(10.0);
  adopt();
  now += 100 * kMs;
  goal(2, kLow);
  planned();
  adopt();
  EXPECT_FALSE(isFinal(sink.last(1)->status));  // spliced into: it runs until 2 starts
  goal(3, kStow);
  planned();
  adopt();  // spliced 30 ms ahead, before 2's segment starts: 2 never runs
  EXPECT_EQ(sink.last(2)->status, S::kCancelled);
  EXPECT_EQ(reason(2), "superseded by request 3");
}

TEST_F(Transitions, AGoalWaitsWhileTheChainIsFullAndTheTimerStartsIt) {
  hold(kStow);
  goal(1, kHigh);
  planned(10.0);
  adopt();
  // Splices 1 ms apart, each 30 ms ahead: none has started, so none can be pruned.
  std::int64_t id = 2;
  for (; coordinator.mirror().segmentCount() < kMaxSegments; ++id) {
    now += kMs;
    goal(id, id % 2 == 0 ? kLow : kHigh);
    ASSERT_TRUE(sink.job.has_value()) << id;
    planned();
    adopt();
  }
  now += kMs;
  goal(id, kStow);
  EXPECT_FALSE(sink.job.has_value());
  EXPECT_EQ(statuses(id), std::vector<S>{S::kAccepted});
  coordinator.onTimer(now);  // still full
  EXPECT_FALSE(sink.job.has_value());
  now += 100 * kMs;  // the early segments' successors have started
  coordinator.onTimer(now);
  ASSERT_TRUE(sink.job.has_value());
  EXPECT_EQ(sink.job->request_id, id);
}

// Events a state does not expect are ignored.

TEST_F(Transitions, AResultOfAnotherJobOrWithoutAJobIsIgnored) {
  hold(kStow);
  PlannedMotion motion;
  motion.trajectory = test::makeHermite(kStow, JointVector::Zero(2), kHigh, 1.0, robot);
  coordinator.onPlanResult(7, planner::Result<PlannedMotion>(motion), 0.001, now);  // Idle
  EXPECT_TRUE(coordinator.idle());
  goal(1, kHigh);
  coordinator.onPlanResult(sink.job->job_id + 1, planner::Result<PlannedMotion>(motion), 0.001, now);
  EXPECT_EQ(sink.program, nullptr);
  EXPECT_FALSE(coordinator.idle());
  planned();
  EXPECT_NE(sink.program, nullptr);
}

TEST_F(Transitions, AdoptionOrRejectionOfAnotherProgramIsIgnored) {
  hold(kStow);
  StreamEvent adopted = event(StreamEventKind::kAdopted);
  adopted.program_id = 99;
  coordinator.onStreamEvent(adopted, now);  // Idle
  goal(1, kHigh);
  coordinator.onStreamEvent(adopted, now);  // Planning
  planned();
  StreamEvent rejected = event(StreamEventKind::kRejected);
  rejected.program_id = sink.program->id + 1;
  coordinator.onStreamEvent(adopted, now);  // Posted, another id
  coordinator.onStreamEvent(rejected, now);
  EXPECT_FALSE(coordinator.idle());
  EXPECT_EQ(coordinator.mirror().segmentCount(), 0);
  EXPECT_EQ(sink.jobs_started.size(), 1u);
  adopt();
  EXPECT_TRUE(coordinator.idle());
}

TEST_F(Transitions, ExecutingIsPublishedOnceAndANewExecutingSegmentSupersedesTheOldOne) {
  hold(kStow);
  goal(1, kHigh);
  planned(10.0);
  adopt();
  streamed(StreamEventKind::kExecuting, 1);
  streamed(StreamEventKind::kExecuting, 1);
  EXPECT_EQ(statuses(1), (std::vector<S>{S::kAccepted, S::kPlanning, S::kExecuting}));
  now += 100 * kMs;
  goal(2, kLow);
  planned();
  adopt();
  streamed(StreamEventKind::kExecuting, 2);
  EXPECT_EQ(statuses(1), (std::vector<S>{S::kAccepted, S::kPlanning, S::kExecuting, S::kCancelled}));
  EXPECT_EQ(reason(1), "superseded by request 2");
  EXPECT_EQ(sink.last(2)->status, S::kExecuting);
}

TEST_F(Transitions, StreamEventsOfRequestsWithoutAnOpenGoalPublishNothing) {
  hold(kStow);
  streamed(StreamEventKind::kExecuting, 5);
  streamed(StreamEventKind::kDone, 5);
  streamed(StreamEventKind::kFault, 5);
  EXPECT_TRUE(sink.statuses.empty());
  ASSERT_EQ(sink.notes.size(), 1u);
  EXPECT_NE(sink.notes[0].find("fault: setpoint of request 5"), std::string::npos);
  EXPECT_EQ(coordinator.counters().goals_done, 0);
}

TEST_F(Transitions, AGoalReusingAnOpenIdReplacesIt) {
  hold(kStow);
  goal(1, kHigh);
  goal(1, kLow);
  EXPECT_EQ(statuses(1), (std::vector<S>{S::kAccepted, S::kPlanning, S::kCancelled, S::kAccepted}));
  EXPECT_EQ(sink.statuses[2].reason, "superseded by request 1");
}

TEST_F(Transitions, AGoalRefusedOnArrivalLeavesTheStateAsItWas) {
  hold(kStow);
  goal(1, kHigh);
  goal(2, kLow, GateReason::kNoHeartbeat);
  goal(3, (JointVector{{5.0, 1.0}}));
  EXPECT_EQ(statuses(2), std::vector<S>{S::kRejected});
  EXPECT_EQ(statuses(3), std::vector<S>{S::kRejected});
  planned();
  adopt();
  EXPECT_TRUE(coordinator.idle());
  EXPECT_EQ(sink.jobs_started.size(), 1u);
}

// ARM_CANCEL's release (stream region: Streaming -> Released -> Stopped -> Streaming).

TEST_F(Transitions, ReleasedToStoppedOnAGoalThenStreamingOnlyOnTheHoldAfterTheRelease) {
  hold(kStow);
  goal(1, kHigh);
  planned(10.0);
  adopt();
  streamed(StreamEventKind::kExecuting, 1);
  coordinator.onCancel(CancelRequest{CancelRequest::kActive, CancelAction::kRelease}, now);
  EXPECT_TRUE(coordinator.released());
  EXPECT_EQ(sink.release_generation, 1u);
  EXPECT_EQ(sink.last(1)->status, S::kCancelled);

  goal(2, kLow, GateReason::kReleased);  // the gate says released: the goal ends the release
  EXPECT_FALSE(coordinator.released());
  EXPECT_EQ(sink.release_generation, 2u);
  EXPECT_EQ(statuses(2), std::vector<S>{S::kAccepted});
  // A hold the streamer took before it saw the release: the goal still waits.
  hold(kStow);
  EXPECT_TRUE(sink.jobs_started.size() == 1u);
  // The streamer's stop for the release cancels nothing: the goal open now came after it.
  generation = 2;
  stopped(GateReason::kReleased);
  EXPECT_EQ(statuses(2), std::vector<S>{S::kAccepted});
  hold(kLow);  // the hold at the measured position after the release
  ASSERT_EQ(sink.jobs_started.size(), 2u);
  EXPECT_EQ(sink.jobs_started[1].request.start, kLow);
  EXPECT_EQ(statuses(2), (std::vector<S>{S::kAccepted, S::kPlanning}));
}

TEST_F(Transitions, ReleasedStaysReleasedWhenTheGateClosesForAnotherReason) {
  hold(kStow);
  coordinator.onCancel(CancelRequest{CancelRequest::kActive, CancelAction::kRelease}, now);
  stopped(GateReason::kRobotDisabled);  // the streamer stopped before it saw the release
  EXPECT_TRUE(coordinator.released());
  generation = 1;
  stopped(GateReason::kReleased);
  EXPECT_TRUE(coordinator.released());
  goal(1, kHigh, GateReason::kReleased);
  EXPECT_FALSE(coordinator.released());
  generation = 2;
  hold(kLow);
  ASSERT_EQ(sink.jobs_started.size(), 1u);
  EXPECT_EQ(sink.jobs_started[0].request.start, kLow);
}

// ARM_CANCEL's hold in the pipeline.

TEST_F(Transitions, AHoldWhilePostedLetsTheProgramBeAdoptedThenBrakesIt) {
  hold(kStow);
  goal(1, kHigh);
  planned(10.0);
  ASSERT_NE(sink.program, nullptr);
  coordinator.onCancel(CancelRequest{1, CancelAction::kHold}, now);
  EXPECT_EQ(sink.last(1)->status, S::kCancelled);
  EXPECT_TRUE(sink.jobs_started.size() == 1u);  // the stop waits for the streamer's answer
  adopt();                                      // moving from now on
  now += 100 * kMs;
  coordinator.onTimer(now);
  ASSERT_EQ(sink.jobs_started.size(), 2u);
  EXPECT_EQ(sink.jobs_started[1].request.kind, MotionKind::kStop);
  EXPECT_EQ(sink.jobs_started[1].request_id, 1);
}

TEST_F(Transitions, AHoldWhilePostedAndRejectedIsNotReplanned) {
  hold(kStow);
  goal(1, kHigh);
  planned(10.0);
  coordinator.onCancel(CancelRequest{CancelRequest::kActive, CancelAction::kHold}, now);
  rejectPosted(RejectReason::kLate);
  // Nothing runs: at rest there is nothing to stop, and the cancelled goal is not re-planned.
  EXPECT_EQ(sink.jobs_started.size(), 1u);
  EXPECT_EQ(statuses(1), (std::vector<S>{S::kAccepted, S::kPlanning, S::kCancelled}));
  EXPECT_TRUE(coordinator.idle());
}

TEST_F(Transitions, AStopThatComesBackLateIsReplannedThenGivenUp) {
  hold(kStow);
  goal(1, kHigh);
  planned(10.0);
  adopt();
  streamed(StreamEventKind::kExecuting, 1);
  now += 500 * kMs;
  coordinator.onCancel(CancelRequest{1, CancelAction::kHold}, now);
  for (int i = 0; i < settings().max_late_attempts; ++i) {
    ASSERT_TRUE(sink.job.has_value()) << i;
    EXPECT_EQ(sink.job->request.kind, MotionKind::kStop);
    now += 2000 * kMs;  // far past the splice point
    planned(0.2);
    EXPECT_EQ(sink.program, nullptr);
  }
  EXPECT_FALSE(sink.job.has_value());
  EXPECT_NE(sink.notes.back().find("no stop was planned in time"), std::string::npos) << sink.notes.back();
  EXPECT_TRUE(coordinator.idle());
}

TEST_F(Transitions, ANewGoalReplacesAStopWaitingForTheWorker) {
  hold(kStow);
  goal(1, kHigh);
  planned(10.0);
  adopt();
  streamed(StreamEventKind::kExecuting, 1);
  now += 500 * kMs;
  goal(2, kLow);  // at the worker
  coordinator.onCancel(CancelRequest{2, CancelAction::kHold}, now);
  goal(3, kStow);  // replaces the stop waiting behind 2's plan
  planned();       // 2's plan: dropped
  ASSERT_TRUE(sink.job.has_value());
  EXPECT_EQ(sink.job->request.kind, MotionKind::kMove);
  EXPECT_EQ(sink.job->request_id, 3);
  EXPECT_GT(sink.job->request.start_velocity.norm(), 0.0);  // from the running motion
}

}  // namespace
}  // namespace cyber::daemon

#include "cyber/daemon/goal_coordinator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>

#include "daemon_harness.hpp"

namespace cyber::daemon {
namespace {

using test::Harness;
using S = GoalStatus;

const JointVector kStow{{0.1, 1.2}};
const JointVector kHigh{{1.6, 2.8}};
const JointVector kLow{{0.4, 0.5}};

std::vector<S> sequence(std::initializer_list<S> s) { return s; }

TEST(GoalCoordinator, AGoalAtRestIsAcceptedPlannedExecutedAndDone) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh);
  ASSERT_TRUE(h.runUntilFinal(1));
  EXPECT_EQ(h.sink.of(1), sequence({S::kAccepted, S::kPlanning, S::kExecuting, S::kDone}));
  ASSERT_EQ(h.sink.trajectories.size(), 1u);
  EXPECT_EQ(h.sink.trajectories[0].first, 1);
  EXPECT_GT(h.sink.last(1)->duration_s, 0.0);
  // Settled at the target with gravity feedforward only.
  h.run(0.05);
  const auto& r = h.lastRecord();
  EXPECT_EQ(r.mode, StreamMode::kHolding);
  EXPECT_TRUE(r.setpoints.position.isApprox(kHigh));
  EXPECT_EQ(r.setpoints.velocity, JointVector::Zero(2));
  EXPECT_DOUBLE_EQ(r.setpoints.volts[1], h.robot.drive(1).kG_volts * std::cos(r.setpoints.position[1]));
  EXPECT_EQ(h.coordinator().counters().goals_done, 1);
  EXPECT_TRUE(h.coordinator().idle());
}

TEST(GoalCoordinator, ThePlanStartsFromTheHeldPositionAtRest) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh);
  ASSERT_EQ(h.sink.jobs_started.size(), 1u);
  EXPECT_EQ(h.sink.jobs_started[0].request.start, kStow);
  EXPECT_EQ(h.sink.jobs_started[0].request.start_velocity, JointVector::Zero(2));
  EXPECT_EQ(h.sink.jobs_started[0].request.goal, kHigh);
}

// ARM_GOAL's scene, scene offset and pieces by name reach the planner's request.
TEST(GoalCoordinator, TheGoalsSceneOffsetAndPiecesReachThePlanRequest) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh, "reef", {"algae", "coral"}, 0.25);
  ASSERT_EQ(h.sink.jobs_started.size(), 1u);
  const MotionRequest& request = h.sink.jobs_started[0].request;
  EXPECT_EQ(request.scene, h.robot.sceneIndex("reef"));
  EXPECT_EQ(request.scene_offset_m, 0.25);
  EXPECT_EQ(request.pieces, cyber::test::referencePieces("coral+algae"));
  ASSERT_TRUE(h.runUntilFinal(1));
  EXPECT_EQ(h.sink.last(1)->status, S::kDone);
}

TEST(GoalCoordinator, AGoalOutsideItsScenesOffsetRangeIsRejectedUnplanned) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh, "reef", {}, 0.5);
  h.goal(2, kHigh, "reef", {"cone"});
  EXPECT_EQ(h.sink.of(1), sequence({S::kRejected}));
  EXPECT_NE(h.sink.last(1)->reason.find("scene_offset_m = 0.5 m is outside scene reef's offset range"),
            std::string::npos)
      << h.sink.last(1)->reason;
  EXPECT_EQ(h.sink.of(2), sequence({S::kRejected}));
  EXPECT_NE(h.sink.last(2)->reason.find("unknown game piece 'cone'"), std::string::npos) << h.sink.last(2)->reason;
  EXPECT_TRUE(h.sink.jobs_started.empty());
}

TEST(GoalCoordinator, BadGoalsAreRejectedWithReasonsAndTheDaemonCarriesOn) {
  Harness h;
  h.collision_goals.push_back(JointVector{{0.3, 0.1}});
  h.start(kStow);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  h.rawGoal(Harness::request(1, JointVector{{nan, 1.0}}));
  h.rawGoal(Harness::request(2, JointVector{{0.5, std::numeric_limits<double>::infinity()}}));
  h.goal(3, JointVector{{3.0, 1.0}});
  h.goal(4, JointVector{{0.5, 1.0}}, "moon");
  for (std::int64_t id : {1, 2, 3, 4}) {
    ASSERT_NE(h.sink.last(id), nullptr);
    EXPECT_EQ(h.sink.of(id), sequence({S::kRejected})) << id;
  }
  EXPECT_NE(h.sink.last(1)->reason.find("position[0] (elevator) is not finite"), std::string::npos)
      << h.sink.last(1)->reason;
  EXPECT_NE(h.sink.last(2)->reason.find("position[1] (arm) is not finite"), std::string::npos);
  EXPECT_NE(h.sink.last(3)->reason.find("outside [0, 2]"), std::string::npos);
  EXPECT_NE(h.sink.last(4)->reason.find("unknown scene 'moon'"), std::string::npos);

  h.goal(5, JointVector{{0.3, 0.1}});  // the fake planner says: in collision
  ASSERT_TRUE(h.runUntilFinal(5));
  EXPECT_EQ(h.sink.last(5)->status, S::kRejected);
  EXPECT_NE(h.sink.last(5)->reason.find("goal in collision"), std::string::npos) << h.sink.last(5)->reason;
  EXPECT_NE(h.sink.last(5)->reason.find("l2_branch"), std::string::npos);

  h.goal(6, kHigh);
  ASSERT_TRUE(h.runUntilFinal(6));
  EXPECT_EQ(h.sink.last(6)->status, S::kDone);
  EXPECT_EQ(h.coordinator().counters().goals_rejected, 5);
  EXPECT_EQ(h.coordinator().counters().goals_received, 6);
}

TEST(GoalCoordinator, PlannerFailuresFromTheStartAreFailedNotRejected) {
  Harness h;
  h.plan = [](const MotionRequest&) {
    return planner::Result<PlannedMotion>::failure(planner::PlanStatus::kNoPath, "the search found no path");
  };
  h.start(kStow);
  h.goal(1, kHigh);
  ASSERT_TRUE(h.runUntilFinal(1));
  EXPECT_EQ(h.sink.of(1), sequence({S::kAccepted, S::kPlanning, S::kFailed}));
  EXPECT_EQ(h.sink.last(1)->reason, "no path: the search found no path");
  EXPECT_EQ(h.coordinator().counters().plans_failed, 1);
}

TEST(GoalCoordinator, GoalsWithoutStateOrWhileDisabledAreRejected) {
  Harness h(true);
  h.auto_state = false;
  h.auto_heartbeat = false;
  h.goal(1, kHigh);
  EXPECT_EQ(h.sink.of(1), sequence({S::kRejected}));
  EXPECT_NE(h.sink.last(1)->reason.find("heartbeat"), std::string::npos) << h.sink.last(1)->reason;
  h.heartbeat(true);
  h.goal(2, kHigh);
  EXPECT_NE(h.sink.last(2)->reason.find("no ARM_STATE"), std::string::npos) << h.sink.last(2)->reason;
  h.feedState(kStow);
  h.heartbeat(false);
  h.goal(3, kHigh);
  EXPECT_NE(h.sink.last(3)->reason.find("robot disabled"), std::string::npos) << h.sink.last(3)->reason;
  h.inputs.state_ns -= secondsToNs(1.0);
  h.heartbeat(true);
  h.goal(4, kHigh);
  EXPECT_NE(h.sink.last(4)->reason.find("stale"), std::string::npos) << h.sink.last(4)->reason;
}

TEST(GoalCoordinator, LatestGoalWinsAmongTheGoalsWaitingForThePlanner) {
  Harness h(false, 0.02);  // plans take 20 ms
  h.start(kStow);
  h.goal(1, kHigh);  // starts planning
  h.step();
  h.goal(2, kLow);   // waits
  h.goal(3, kHigh);  // supersedes 2, which never gets planned
  ASSERT_TRUE(h.runUntilFinal(3));
  EXPECT_EQ(h.sink.of(2), sequence({S::kAccepted, S::kCancelled}));
  EXPECT_EQ(h.sink.last(2)->reason, "superseded by request 3");
  // The plan in progress was not wasted: it ran until 3 was spliced into it.
  EXPECT_EQ(h.sink.of(1), sequence({S::kAccepted, S::kPlanning, S::kExecuting, S::kCancelled}));
  EXPECT_EQ(h.sink.last(1)->reason, "superseded by request 3");
  EXPECT_EQ(h.sink.of(3), sequence({S::kAccepted, S::kPlanning, S::kExecuting, S::kDone}));
  ASSERT_EQ(h.sink.jobs_started.size(), 2u);
  EXPECT_GT(h.sink.jobs_started[1].request.start_velocity.norm(), 0.0);  // 3 starts from 1's motion
  EXPECT_EQ(h.sink.trajectories.size(), 2u);
}

TEST(GoalCoordinator, AStreamOfGoalsFasterThanThePlannerStillMovesTheMechanism) {
  Harness h(false, 0.02);
  h.start(kStow);
  std::int64_t id = 0;
  int moving_ticks = 0;
  for (int period = 0; period < 200; ++period) {  // a new goal every period for a second
    h.goal(id++, period % 2 == 0 ? kHigh : kLow);
    h.step();
    moving_ticks += h.lastRecord().mode == StreamMode::kMoving ? 1 : 0;
  }
  EXPECT_GT(moving_ticks, 150);
  ASSERT_TRUE(h.runUntilFinal(id - 1, 20.0));
  EXPECT_EQ(h.sink.last(id - 1)->status, S::kDone);
}

TEST(GoalCoordinator, AFloodOfGoalsGivesEveryGoalExactlyOneFinalStatusAndTheLastOneRuns) {
  Harness h(false, 0.004);
  h.start(kStow);
  // 1000 goals at 1 ms spacing (1000/s for one second); five per stream period.
  std::int64_t id = 0;
  for (int period = 0; period < 200; ++period) {
    for (int k = 0; k < 5; ++k, ++id) {
      const double u = static_cast<double>(id % 17) / 16.0;
      h.goal(id, JointVector{{0.1 + 1.7 * u, 0.3 + 2.5 * (1.0 - u)}});
    }
    h.step();
  }
  ASSERT_TRUE(h.runUntilFinal(id - 1, 20.0));
  h.run(0.1);
  std::map<S, int> finals;
  for (std::int64_t i = 0; i < id; ++i) {
    int count = 0;
    for (S s : h.sink.of(i)) {
      if (isFinal(s)) {
        ++count;
        ++finals[s];
      }
    }
    ASSERT_EQ(count, 1) << "request " << i;
  }
  EXPECT_EQ(h.sink.last(id - 1)->status, S::kDone);
  EXPECT_EQ(finals[S::kCancelled] + finals[S::kDone], 1000);
  EXPECT_TRUE(h.coordinator().idle());
}

// Largest change of a quantity between consecutive streamed ticks.
double largestStep(const std::vector<test::TickRecord>& records, bool velocity, std::size_t from, std::size_t to) {
  double largest = 0.0;
  for (std::size_t i = from + 1; i < to; ++i) {
    if (!records[i].sent || !records[i - 1].sent) continue;
    const JointVector& a = velocity ? records[i - 1].setpoints.velocity : records[i - 1].setpoints.position;
    const JointVector& b = velocity ? records[i].setpoints.velocity : records[i].setpoints.position;
    largest = std::max(largest, (b - a).cwiseAbs().maxCoeff());
  }
  return largest;
}

TEST(GoalCoordinator, AGoalDuringMotionIsSplicedWithContinuousPositionAndVelocity) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh);
  h.run(0.3);  // well inside the first motion
  ASSERT_EQ(h.lastRecord().mode, StreamMode::kMoving);
  const std::size_t before = h.records.size();
  const MonoNs goal_time = h.now;
  h.goal(2, kLow);
  ASSERT_EQ(h.sink.jobs_started.size(), 2u);
  const MotionRequest& request = h.sink.jobs_started[1].request;
  EXPECT_GT(request.start_velocity.norm(), 0.1);  // planned from a moving state
  ASSERT_TRUE(h.runUntilFinal(2));
  EXPECT_EQ(h.sink.of(1), sequence({S::kAccepted, S::kPlanning, S::kExecuting, S::kCancelled}));
  EXPECT_EQ(h.sink.last(1)->reason, "superseded by request 2");
  EXPECT_EQ(h.sink.of(2), sequence({S::kAccepted, S::kPlanning, S::kExecuting, S::kDone}));

  // The splice point is the commanded state one planning budget after the goal.
  ASSERT_EQ(h.sink.trajectories.size(), 2u);
  const MonoNs splice = h.sink.trajectories[1].second;
  EXPECT_GE(splice, goal_time + secondsToNs(0.03));
  std::size_t switch_index = 0;
  for (std::size_t i = before; i < h.records.size(); ++i) {
    if (h.records[i].request_id == 2) {
      switch_index = i;
      break;
    }
  }
  ASSERT_GT(switch_index, before);
  EXPECT_GE(h.records[switch_index].now, splice);
  EXPECT_LT(h.records[switch_index - 1].now, splice);
  // The streamed command across the switch changes no more than it does elsewhere in the motions.
  const double position_step = largestStep(h.records, false, switch_index - 1, switch_index + 1);
  const double velocity_step = largestStep(h.records, true, switch_index - 1, switch_index + 1);
  const double usual_position = largestStep(h.records, false, before - 40, h.records.size());
  const double usual_velocity = std::max(largestStep(h.records, true, before - 40, switch_index - 1),
                                         largestStep(h.records, true, switch_index + 1, h.records.size()));
  EXPECT_LE(position_step, usual_position + 1e-12);
  EXPECT_LE(velocity_step, usual_velocity + 1e-12);
  // And the new plan's first sample is exactly the old plan's state at the splice point.
  EXPECT_LT((request.start - h.coordinator().mirror().segment(0).source->at(0).position).norm(), 1.0);
}

TEST(GoalCoordinator, ASegmentNoTickSampledIsCancelledWhenTheNextOneStarts) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh);
  h.run(0.3);
  h.goal(2, kLow);
  h.step();  // plan 2 is back and adopted: it starts 30 ms after its goal
  h.step();
  h.goal(3, kStow);
  h.step();
  h.step();  // plan 3 adopted, starting after plan 2
  ASSERT_EQ(h.coordinator().mirror().segmentCount(), 3);
  EXPECT_FALSE(isFinal(h.sink.last(2)->status));
  // Had plan 3 started less than a period after plan 2, no tick would have streamed plan 2.
  StreamEvent executing;
  executing.kind = StreamEventKind::kExecuting;
  executing.request_id = 3;
  h.coordinator().onStreamEvent(executing, h.now);
  EXPECT_EQ(h.sink.last(1)->status, S::kCancelled);
  EXPECT_EQ(h.sink.last(2)->status, S::kCancelled);
  EXPECT_EQ(h.sink.last(2)->reason, "superseded by request 3");
  EXPECT_EQ(h.sink.last(3)->status, S::kExecuting);
}

// The worker's result delivered at `at`, between stream ticks, as the event loop may see it.
void deliverPlan(Harness& h, MonoNs at) {
  ASSERT_TRUE(h.sink.job.has_value());
  const PlanJob job = *h.sink.job;
  h.sink.job.reset();
  h.coordinator().onPlanResult(job.job_id, h.plan(job.request), 0.001, at);
}

TEST(GoalCoordinator, ASegmentNoTickSampledIsCancelledWhenASpliceAfterItsSuccessorsStartDropsIt) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh);
  h.run(0.3);
  ASSERT_EQ(h.lastRecord().mode, StreamMode::kMoving);
  h.setPlanTime(1e9);                            // from here plans are delivered by hand, at times between ticks
  const MonoNs tick = h.now - Harness::kPeriod;  // the last tick
  const MonoNs ms = 1'000'000;
  // Goal 2 at tick + 1 ms starts at tick + 31 ms; goal 3, waiting until 2 is adopted at tick + 5 ms,
  // starts at tick + 35 ms: no tick falls between them, so no tick ever streams 2.
  h.now = tick + 1 * ms;
  h.goal(2, kLow);
  deliverPlan(h, tick + 2 * ms);
  h.now = tick + 3 * ms;
  h.goal(3, kStow);
  h.now = tick + Harness::kPeriod;
  h.step();  // adopts 2, starts planning 3
  deliverPlan(h, tick + 7 * ms);
  h.step();  // adopts 3
  ASSERT_EQ(h.coordinator().mirror().segmentCount(), 3);
  h.now = tick + 12 * ms;
  h.goal(4, kHigh);  // starts at tick + 42 ms
  h.now = tick + 3 * Harness::kPeriod;
  while (h.now < tick + 35 * ms) h.step();
  // Plan 4 is back just as 3 starts, before the tick that streams 3: its splice leaves out 2 (over,
  // since 3 has started), and the streamer adopts it before it samples 3.
  deliverPlan(h, h.now);
  h.step();
  ASSERT_EQ(h.sink.last(3)->status, S::kExecuting);
  ASSERT_NE(h.sink.last(2), nullptr);
  EXPECT_EQ(h.sink.of(2), sequence({S::kAccepted, S::kPlanning, S::kCancelled}));
  EXPECT_EQ(h.sink.last(2)->reason, "superseded by request 3");
  EXPECT_EQ(h.sink.last(1)->status, S::kCancelled);
}

// Seeded random floods with the event loop's timing free: goals and plan results land at any
// millisecond between ticks, plans take 1-60 ms (so the budget, and the splice points, move).
// Every goal gets exactly one final status.
TEST(GoalCoordinator, RandomFloodsBetweenTicksGiveEveryGoalExactlyOneFinalStatus) {
  const MonoNs ms = 1'000'000;
  for (unsigned seed = 1; seed <= 100; ++seed) {
    std::mt19937 random(seed);
    // Mostly quick plans with a slow one now and then: the budget jumps up, and down again when the
    // slow plan leaves its window.
    std::uniform_int_distribution<int> quick_ms(1, 4), slow_ms(20, 60), sub_ms(0, Harness::kPeriod / ms - 1);
    const auto plan_ms = [&](std::mt19937& r) { return r() % 8 == 0 ? slow_ms(r) : quick_ms(r); };
    Harness h;
    h.start(kStow);
    h.run(0.01);
    h.setPlanTime(1e9);  // plans are delivered below
    MonoNs plan_due = kNever;
    std::int64_t id = 0;
    const std::int64_t goals = 300;
    for (int period = 0; period < 4000 && (id < goals || !h.coordinator().idle()); ++period) {
      const MonoNs tick = h.now;
      const MonoNs goal_at = tick - Harness::kPeriod + (sub_ms(random) + 1) * ms;
      for (MonoNs t = tick - Harness::kPeriod + ms; t <= tick; t += ms) {
        h.now = t;
        if (h.sink.job && plan_due == kNever) plan_due = h.sink.job_started_ns + plan_ms(random) * ms;
        if (h.sink.job && t >= plan_due) {
          const PlanJob job = *h.sink.job;
          h.sink.job.reset();
          plan_due = kNever;
          h.coordinator().onPlanResult(job.job_id, h.plan(job.request), nsToSeconds(t - h.sink.job_started_ns), t);
        }
        if (t == goal_at && id < goals) {
          const double u = static_cast<double>(random() % 17) / 16.0;
          h.goal(id++, JointVector{{0.1 + 1.7 * u, 0.3 + 2.5 * (1.0 - u)}});
        }
      }
      h.now = tick;
      h.step();
    }
    ASSERT_EQ(id, goals) << "seed " << seed;
    ASSERT_TRUE(h.coordinator().idle()) << "seed " << seed;
    h.run(5.0);  // the last motion ends
    for (std::int64_t i = 0; i < goals; ++i) {
      const auto statuses = h.sink.of(i);
      ASSERT_EQ(std::count_if(statuses.begin(), statuses.end(), isFinal), 1)
          << "seed " << seed << ", request " << i << ", statuses " << ::testing::PrintToString(statuses);
    }
  }
}

TEST(GoalCoordinator, ALatePlanIsReplannedFromALaterPointAndStillSplicesSmoothly) {
  Harness h(false, 0.002);
  h.start(kStow);
  h.goal(1, kHigh);
  h.run(0.2);
  h.setPlanTime(0.06);  // slower than the 30 ms budget: the first attempt misses its splice point
  const std::size_t before = h.records.size();
  h.goal(2, kLow);
  ASSERT_TRUE(h.runUntilFinal(2));
  EXPECT_EQ(h.sink.last(2)->status, S::kDone);
  EXPECT_GE(h.coordinator().counters().plans_late, 1);
  ASSERT_FALSE(h.sink.notes.empty());
  EXPECT_NE(h.sink.notes[0].find("re-planning from a later point"), std::string::npos) << h.sink.notes[0];
  // The retry was planned with the measured (longer) budget.
  EXPECT_GT(h.coordinator().budgetS(), 0.06);
  ASSERT_GE(h.sink.jobs_started.size(), 3u);
  EXPECT_GT(h.sink.jobs_started.back().request.start_velocity.norm(), 0.0);
  std::size_t switch_index = before;
  while (switch_index < h.records.size() && h.records[switch_index].request_id != 2) ++switch_index;
  ASSERT_LT(switch_index, h.records.size());
  const double velocity_step = largestStep(h.records, true, switch_index - 1, switch_index + 1);
  const double usual = std::max(largestStep(h.records, true, 0, switch_index - 1),
                                largestStep(h.records, true, switch_index + 1, h.records.size()));
  EXPECT_LE(velocity_step, usual + 1e-12);
}

// Goal 1 from kStow to kHigh and, 0.2 s into it, goal 2 to kLow, every plan from then on taking
// plan_time_s: true once goal 2 has its final status.
bool secondGoalPlannedIn(Harness& h, double plan_time_s) {
  h.start(kStow);
  h.goal(1, kHigh);
  h.run(0.2);
  h.setPlanTime(plan_time_s);
  h.goal(2, kLow);
  return h.runUntilFinal(2, 30.0);
}

TEST(GoalCoordinator, APlanLateOnceIsReplannedFromRestWhenTheMotionEndsWithinTheNewBudget) {
  Harness h(false, 0.002);
  ASSERT_TRUE(secondGoalPlannedIn(h, 1.5));  // longer than the rest of motion 1
  EXPECT_EQ(h.sink.last(1)->status, S::kDone);
  EXPECT_EQ(h.sink.last(2)->status, S::kDone);
  EXPECT_EQ(h.coordinator().counters().plans_late, 1);
  ASSERT_EQ(h.sink.jobs_started.size(), 3u);
  EXPECT_TRUE(h.sink.jobs_started[2].request.start.isApprox(kHigh));  // from where motion 1 rests
  EXPECT_EQ(h.sink.jobs_started[2].request.start_velocity, JointVector::Zero(2));
}

// Motion 1 (1.4 s) is still running when the late plan is back, 0.6 s from its end: the new budget
// (1.25 * 0.6 s + a margin) outlasts it, the goal is planned from its end, and the log says why.
TEST(GoalCoordinator, ABudgetOutlastingTheRunningMotionPlansFromItsEndAndSaysSo) {
  Harness h(false, 0.002);
  ASSERT_TRUE(secondGoalPlannedIn(h, 0.6));
  EXPECT_EQ(h.sink.last(1)->status, S::kDone);
  EXPECT_EQ(h.sink.last(2)->status, S::kDone);
  ASSERT_EQ(h.sink.jobs_started.size(), 3u);
  EXPECT_TRUE(h.sink.jobs_started[2].request.start.isApprox(kHigh));
  ASSERT_EQ(h.sink.notes.size(), 2u);
  EXPECT_EQ(h.sink.notes[1],
            "request 2: the running motion ends in 601.6 ms, within the planning budget of 756.0 ms; planning from "
            "where it ends");
}

TEST(GoalCoordinator, PlansThatAreAlwaysLateFallBackToStartingWhereTheMotionEnds) {
  Harness h(false, 0.002);
  // Motion 1 is long (8 s) so every re-plan from a later point is still a splice into it.
  h.plan = [&h](const MotionRequest& request) {
    PlannedMotion motion;
    const double duration = request.goal == kHigh ? 8.0 : 0.5;
    motion.trajectory = test::makeHermite(request.start, request.start_velocity, request.goal, duration, h.robot);
    return planner::Result<PlannedMotion>(motion);
  };
  // Every plan takes longer than any budget can absorb (the budget is capped at 1 s).
  ASSERT_TRUE(secondGoalPlannedIn(h, 1.5));
  EXPECT_EQ(h.sink.last(2)->status, S::kDone);
  EXPECT_EQ(h.sink.last(1)->status, S::kDone);  // request 1 was finished, not cut
  bool fell_back = false;
  for (const auto& note : h.sink.notes) fell_back |= note.find("planning from where it ends") != std::string::npos;
  EXPECT_TRUE(fell_back);
  EXPECT_EQ(h.coordinator().counters().plans_late, 3);
  EXPECT_TRUE(h.sink.jobs_started.back().request.start.isApprox(kHigh));
  EXPECT_TRUE(h.lastRecord().setpoints.position.isApprox(kLow));
}

TEST(GoalCoordinator, GateClosingMidMotionCancelsTheGoalAndReEnableHoldsTheMeasuredPosition) {
  Harness h(true);
  h.start(kStow);
  h.goal(1, kHigh);
  h.run(0.3);
  ASSERT_EQ(h.lastRecord().mode, StreamMode::kMoving);
  h.auto_heartbeat = false;
  h.run(0.2);
  EXPECT_EQ(h.sink.last(1)->status, S::kCancelled);
  EXPECT_NE(h.sink.last(1)->reason.find("motion stopped"), std::string::npos) << h.sink.last(1)->reason;
  EXPECT_FALSE(h.lastRecord().sent);
  EXPECT_EQ(h.lastRecord().mode, StreamMode::kRobotDisabled);
  // While disabled, goals are rejected.
  h.goal(2, kLow);
  EXPECT_EQ(h.sink.of(2), sequence({S::kRejected}));
  // Re-enabled with the mechanism somewhere else: hold there, then plan from there.
  const JointVector sagged{{0.5, 1.4}};
  h.auto_state = false;
  h.feedState(sagged);
  h.auto_heartbeat = true;
  h.heartbeat(true);
  h.step();
  EXPECT_TRUE(h.records.back().sent);
  EXPECT_EQ(h.records.back().setpoints.position, sagged);
  EXPECT_EQ(h.records.back().setpoints.velocity, JointVector::Zero(2));
  h.auto_state = true;
  h.goal(3, kLow);
  EXPECT_EQ(h.sink.jobs_started.back().request.start, sagged);
  ASSERT_TRUE(h.runUntilFinal(3));
  EXPECT_EQ(h.sink.last(3)->status, S::kDone);
}

TEST(GoalCoordinator, GateClosedWhenThePlanArrivesCancelsTheGoal) {
  Harness h(true, 0.05);
  h.start(kStow);
  h.goal(1, kHigh);
  h.auto_heartbeat = false;
  h.broadcastDisable();
  ASSERT_TRUE(h.runUntilFinal(1));
  EXPECT_EQ(h.sink.of(1), sequence({S::kAccepted, S::kPlanning, S::kCancelled}));
  EXPECT_EQ(h.sink.last(1)->reason, "motion stopped while planning: broadcast disable received");
}

TEST(GoalCoordinator, ABriefDisableWhilePlanningReplansFromTheNewHold) {
  Harness h(true, 0.05);
  h.start(kStow);
  h.goal(1, kHigh);
  h.broadcastDisable();  // lifted by the next enabled heartbeat, before the plan is back
  ASSERT_TRUE(h.runUntilFinal(1));
  EXPECT_EQ(h.sink.of(1), sequence({S::kAccepted, S::kPlanning, S::kExecuting, S::kDone}));
  EXPECT_EQ(h.sink.jobs_started.size(), 2u);
}

TEST(GoalCoordinator, ShutdownHoldsTheCommandedPositionAndCancelsOpenGoals) {
  Harness h;
  h.start(kStow);
  h.goal(1, kHigh);
  h.run(0.3);
  const JointVector commanded = h.lastRecord().setpoints.position;
  h.stop_requested = true;
  h.step();
  h.coordinator().onShutdown(h.now);
  EXPECT_EQ(h.sink.last(1)->status, S::kCancelled);
  EXPECT_EQ(h.sink.last(1)->reason, "daemon shutting down");
  h.run(0.05);
  EXPECT_EQ(h.lastRecord().mode, StreamMode::kHolding);
  EXPECT_EQ(h.lastRecord().setpoints.velocity, JointVector::Zero(2));
  EXPECT_LT((h.lastRecord().setpoints.position - commanded).norm(), 0.1);
}

TEST(GoalCoordinator, AGoalToWhereTheArmAlreadyIsFinishesAtOnce) {
  Harness h;
  h.plan = [&h](const MotionRequest& request) {
    PlannedMotion motion;
    motion.trajectory = test::makeHermite(request.start, request.start_velocity, request.goal, 0.0, h.robot);
    return planner::Result<PlannedMotion>(motion);
  };
  h.start(kStow);
  h.goal(1, kStow);
  ASSERT_TRUE(h.runUntilFinal(1));
  EXPECT_EQ(h.sink.of(1), sequence({S::kAccepted, S::kPlanning, S::kExecuting, S::kDone}));
}

}  // namespace
}  // namespace cyber::daemon

// The moving-start strategies (docs/moving-starts.md): each one on its own, and the chooser that
// times a candidate only while it can still win.

#include <array>
#include <limits>
#include <random>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "motion/moving_start_strategies.hpp"
#include "motion/scene_planners.hpp"
#include "motion/timed_plan.hpp"
#include "reference_model.hpp"

namespace cyber::planner {
namespace {

constexpr double kStepS = 0.001;

const MotionPlanner& referencePlanner() {
  static const MotionPlanner planner = MotionPlanner::create(test::referenceModel()).value();
  return planner;
}

// A state in the middle of the reef scene's free space, moving up and out, and a goal below it.
PlanRequest aheadRequest() {
  PlanRequest request;
  request.start = JointVector{{0.6, 3.0}};
  request.goal = JointVector{{1.2, 3.6}};
  request.start_velocity = JointVector{{0.8, 1.0}};
  return request;
}

// The same state moving away from the goal: stopping first is the better candidate.
PlanRequest awayRequest() {
  PlanRequest request = aheadRequest();
  request.goal = JointVector{{0.3, 2.6}};
  return request;
}

TEST(MovingStartStrategies, AreListedInOrderWithTheirReasons) {
  const auto strategies = movingStartStrategies();
  ASSERT_EQ(strategies.size(), 2u);
  EXPECT_EQ(strategies[0].name, "leaving along the velocity");
  EXPECT_EQ(strategies[0].prepare, &leaveAlongVelocity);
  EXPECT_EQ(strategies[1].name, "stopping first");
  EXPECT_EQ(strategies[1].prepare, &stopFirst);
  for (const MovingStartStrategy& strategy : strategies) EXPECT_FALSE(strategy.reason.empty()) << strategy.name;
}

TEST(MovingStartStrategies, LeavingAlongTheVelocityStartsWithThatVelocity) {
  const PlanRequest request = aheadRequest();
  const MovingStartCandidate candidate =
      leaveAlongVelocity(MovingStartInputs{test::referenceModel(), drawnPathPlanner(referencePlanner(), 0), request});
  ASSERT_FALSE(candidate.refused) << candidate.refused->message;
  EXPECT_TRUE(std::isfinite(candidate.estimate_s));
  EXPECT_LT(candidate.lower_bound_s, candidate.estimate_s);
  const Result<Plan> plan = candidate.time();
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  const Trajectory& trajectory = *plan.value().trajectory;
  EXPECT_FALSE(plan.value().method.has(PlanMethod::kStoppedFirst)) << plan.value().method.name();
  EXPECT_LT((trajectory.sample(0.0).qdot - request.start_velocity).norm(), 1e-6);
  EXPECT_LT((trajectory.sample(trajectory.duration_s()).q - request.goal).norm(), 1e-6);
  // Its estimate is what the chooser compares: within the reachability pass's error of the time.
  EXPECT_GE(trajectory.duration_s(), candidate.lower_bound_s);
}

// Moving straight away from the goal, the path leaving along the velocity would fold back on
// itself: it promises nothing (the mechanism would stop at the fold), so stopping first is timed
// and the plan is its; without that candidate the folding one is timed after all.
TEST(MovingStartStrategies, LeavingAlongTheVelocityOnAPathThatFoldsBackIsTheLastResort) {
  PlanRequest request = aheadRequest();
  request.goal = request.start - 0.4 * request.start_velocity.normalized();
  const MovingStartInputs inputs{test::referenceModel(), drawnPathPlanner(referencePlanner(), 0), request};
  const MovingStartCandidate candidate = leaveAlongVelocity(inputs);
  ASSERT_FALSE(candidate.refused) << candidate.refused->message;
  EXPECT_EQ(candidate.estimate_s, std::numeric_limits<double>::infinity());
  EXPECT_EQ(candidate.lower_bound_s, std::numeric_limits<double>::infinity());
  const Result<Plan> plan = planMovingStart(inputs, movingStartStrategies());
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  EXPECT_TRUE(plan.value().method.has(PlanMethod::kStoppedFirst)) << plan.value().method.name();
  const Result<Plan> alone = planMovingStart(inputs, movingStartStrategies().first(1));
  ASSERT_TRUE(alone.ok()) << alone.error().message;
  EXPECT_FALSE(alone.value().method.has(PlanMethod::kStoppedFirst)) << alone.value().method.name();
  EXPECT_LT((alone.value().trajectory->sample(0.0).qdot - request.start_velocity).norm(), 1e-6);
}

TEST(MovingStartStrategies, StoppingFirstComesToRestAlongTheVelocityThenPlans) {
  const PlanRequest request = awayRequest();
  const MovingStartCandidate candidate =
      stopFirst(MovingStartInputs{test::referenceModel(), drawnPathPlanner(referencePlanner(), 0), request});
  ASSERT_FALSE(candidate.refused) << candidate.refused->message;
  const Result<Plan> plan = candidate.time();
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  EXPECT_TRUE(plan.value().method.has(PlanMethod::kStoppedFirst)) << plan.value().method.name();
  const Trajectory& trajectory = *plan.value().trajectory;
  EXPECT_LT((trajectory.sample(0.0).qdot - request.start_velocity).norm(), 1e-6);
  // In its first half it comes to rest (the slowest instant there, found at 10 us steps, is all but
  // still) at a point along the start velocity.
  double slowest_t = 0.0;
  double slowest = request.start_velocity.norm();
  for (double t = kStepS; t < 0.5 * trajectory.duration_s(); t += 0.01 * kStepS) {
    if (trajectory.sample(t).qdot.norm() < slowest) {
      slowest = trajectory.sample(t).qdot.norm();
      slowest_t = t;
    }
  }
  EXPECT_LT(slowest, 0.01 * request.start_velocity.norm());
  const JointVector along = trajectory.sample(slowest_t).q - request.start;
  EXPECT_GT(along.dot(request.start_velocity), 0.0);
  EXPECT_LT(std::abs(along.x() * request.start_velocity.y() - along.y() * request.start_velocity.x()),
            1e-4 * request.start_velocity.norm());
  EXPECT_GE(trajectory.duration_s(), candidate.lower_bound_s);
}

TEST(MovingStartStrategies, StoppingFirstIsRefusedWhenTheJointLimitComesFirst) {
  const RobotModel& model = test::referenceModel();
  PlanRequest request = aheadRequest();
  request.start.x() = model.range(0).max - 0.002;
  request.start_velocity = JointVector{{2.5, 0.0}};
  const MovingStartCandidate candidate =
      stopFirst(MovingStartInputs{model, drawnPathPlanner(referencePlanner(), 0), request});
  ASSERT_TRUE(candidate.refused);
  EXPECT_EQ(candidate.refused->status, PlanStatus::kInfeasibleStart) << candidate.refused->message;
  EXPECT_FALSE(candidate.time);
}

TEST(MovingStartStrategies, TheWholeListIsWhatMotionPlannerPlans) {
  const RobotModel& model = test::referenceModel();
  const PathPlanner& paths = drawnPathPlanner(referencePlanner(), 0);
  std::mt19937 rng(20261205);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int compared = 0;
  for (int i = 0; i < 12; ++i) {
    PlanRequest request;
    const CollisionWorld& world = paths.world(request.pieces);
    do request.start = JointVector{{0.1 + 1.8 * std::abs(unit(rng)), 3.0 + 2.5 * std::abs(unit(rng))}};
    while (world.distance(request.start).value < model.clearance_m);
    do request.goal = JointVector{{0.1 + 1.8 * std::abs(unit(rng)), 3.0 + 2.5 * std::abs(unit(rng))}};
    while (world.distance(request.goal).value < model.clearance_m);
    const double v0 = unit(rng);
    const double v1 = unit(rng);
    request.start_velocity = JointVector{{v0, 3.0 * v1}};
    const Result<Plan> listed = planMovingStart(MovingStartInputs{model, paths, request}, movingStartStrategies());
    const Result<Plan> planned = referencePlanner().plan(request);
    ASSERT_EQ(listed.ok(), planned.ok()) << i;
    if (!listed) {
      EXPECT_EQ(listed.error().message, planned.error().message);
      continue;
    }
    ++compared;
    EXPECT_EQ(listed.value().trajectory->duration_s(), planned.value().trajectory->duration_s()) << i;
    EXPECT_EQ(listed.value().method, planned.value().method) << i;
  }
  EXPECT_GE(compared, 6);
}

// The chooser, with strategies whose candidates are made up around real plans from rest.
struct Fake {
  int prepared = 0;
  int timed = 0;
  MovingStartCandidate candidate;
};
std::array<Fake, 2> fakes;

Plan restPlan(std::string_view method) {  // a literal: the plan keeps a view of it
  PlanRequest request = aheadRequest();
  request.start_velocity = JointVector::Zero(2);
  Plan plan = referencePlanner().plan(request).value();
  plan.method.strategy = method;
  return plan;
}

// A plan whose columns disagree at 1 ms: along the rest plan's path in 15.5 ms, accelerating
// uniformly to halfway and braking after (the trapezoid across that jump errs most mid-sample).
Plan disagreeingPlan(std::string_view method) {
  Plan plan = restPlan(method);
  const double length = plan.trajectory->path().length();
  const double mid_speed = 2.0 * length / 0.0155;
  plan.trajectory = std::make_shared<const Trajectory>(
      Trajectory::create(plan.trajectory->sharedPath(), plan.trajectory->drives(), {0.0, 0.5 * length, length},
                         {0.0, mid_speed * mid_speed, 0.0})
          .value());
  return plan;
}

template <int I>
MovingStartCandidate fakePrepare(const MovingStartInputs&) {
  ++fakes[I].prepared;
  MovingStartCandidate out = fakes[I].candidate;
  std::function<Result<Plan>()> inner = out.time;
  if (inner) {
    out.time = [inner] {
      ++fakes[I].timed;
      return inner();
    };
  }
  return out;
}

constexpr std::array<MovingStartStrategy, 2> kFakeStrategies{{
    {"first", "a test's", &fakePrepare<0>},
    {"second", "a test's", &fakePrepare<1>},
}};

MovingStartCandidate timedAs(double estimate_s, double lower_bound_s, Result<Plan> plan) {
  MovingStartCandidate out;
  out.estimate_s = estimate_s;
  out.lower_bound_s = lower_bound_s;
  out.time = [plan] { return plan; };
  return out;
}

MovingStartCandidate refusedAs(PlanStatus status, const std::string& reason) {
  MovingStartCandidate out;
  out.refused = PlanError{status, reason};
  return out;
}

Result<Plan> chooseFakes() {
  const PlanRequest request = aheadRequest();
  return planMovingStart(MovingStartInputs{test::referenceModel(), drawnPathPlanner(referencePlanner(), 0), request},
                         kFakeStrategies);
}

class MovingStartChooser : public ::testing::Test {
 protected:
  void SetUp() override { fakes = {}; }
};

TEST_F(MovingStartChooser, DoesNotTimeACandidateThatCannotBeatOneTimedAlready) {
  const Plan plan = restPlan("first");
  const double duration = plan.trajectory->duration_s();
  fakes[0].candidate = timedAs(duration, 0.9 * duration, plan);
  fakes[1].candidate = timedAs(2.0 * duration, 1.5 * duration, restPlan("second"));
  const Result<Plan> chosen = chooseFakes();
  ASSERT_TRUE(chosen.ok());
  EXPECT_EQ(chosen.value().method.strategy, "first");
  EXPECT_EQ(fakes[0].timed, 1);
  EXPECT_EQ(fakes[1].prepared, 1);
  EXPECT_EQ(fakes[1].timed, 0);
}

TEST_F(MovingStartChooser, TimesACandidateLeftOutWhenTheOneThatPromisedMoreFails) {
  const Plan plan = restPlan("second");
  const double duration = plan.trajectory->duration_s();
  // The first is not timed at first: its lower bound is above the second's estimate.
  fakes[0].candidate = timedAs(3.0 * duration, 2.0 * duration, restPlan("first"));
  fakes[1].candidate = timedAs(duration, 0.9 * duration, Result<Plan>(inconsistentPlan()));
  const Result<Plan> chosen = chooseFakes();
  ASSERT_TRUE(chosen.ok());
  EXPECT_EQ(chosen.value().method.strategy, "first");
  EXPECT_EQ(fakes[0].timed, 1);
  EXPECT_EQ(fakes[1].timed, 1);
}

// A candidate that promises nothing (an infinite bound: leaving along the velocity on a path
// that folds back) is timed only when the other has no plan: refused, or failed when timed.
TEST_F(MovingStartChooser, ALastResortIsTimedOnlyWhenNoOtherCandidateHasAPlan) {
  const double inf = std::numeric_limits<double>::infinity();
  const Plan plan = restPlan("second");
  const double duration = plan.trajectory->duration_s();
  // The strategy chosen, and whether the last resort (the first) was timed, beside `second`.
  const auto chooseBeside = [&](MovingStartCandidate second, std::string_view strategy, int timed) {
    fakes = {};
    fakes[0].candidate = timedAs(inf, inf, restPlan("first"));
    fakes[1].candidate = std::move(second);
    const Result<Plan> chosen = chooseFakes();
    ASSERT_TRUE(chosen.ok());
    EXPECT_EQ(chosen.value().method.strategy, strategy);
    EXPECT_EQ(fakes[0].timed, timed);
  };
  chooseBeside(timedAs(duration, 0.9 * duration, plan), "second", 0);
  // Nor when the other's plan is there but its columns disagree.
  const Plan disagreeing = disagreeingPlan("second");
  ASSERT_FALSE(columnsAgree(test::referenceModel().planner.motion, *disagreeing.trajectory));
  chooseBeside(timedAs(duration, 0.9 * duration, disagreeing), "second", 0);
  chooseBeside(timedAs(duration, 0.9 * duration, Result<Plan>(inconsistentPlan())), "first", 1);
  chooseBeside(refusedAs(PlanStatus::kInfeasibleStart, "cannot brake inside the joint limits"), "first", 1);
}

TEST_F(MovingStartChooser, TheShorterAgreeingPlanWinsAndTiesGoToTheEarlierStrategy) {
  Plan slower = restPlan("first");
  Result<Trajectory> stretched = slowedDown(*slower.trajectory, 1.1);
  ASSERT_TRUE(stretched.ok());
  slower.trajectory = std::make_shared<const Trajectory>(std::move(stretched).value());
  const Plan faster = restPlan("second");
  const double duration = faster.trajectory->duration_s();
  fakes[0].candidate = timedAs(duration, 0.5 * duration, slower);
  fakes[1].candidate = timedAs(duration, 0.5 * duration, faster);
  Result<Plan> chosen = chooseFakes();
  ASSERT_TRUE(chosen.ok());
  EXPECT_EQ(chosen.value().method.strategy, "second");

  fakes = {};
  fakes[0].candidate = timedAs(duration, 0.5 * duration, restPlan("first"));
  fakes[1].candidate = timedAs(duration, 0.5 * duration, restPlan("second"));
  chosen = chooseFakes();
  ASSERT_TRUE(chosen.ok());
  EXPECT_EQ(chosen.value().method.strategy, "first");
}

TEST_F(MovingStartChooser, ARefusalGivesEveryStrategysReason) {
  fakes[0].candidate = refusedAs(PlanStatus::kInfeasibleStart, "cannot leave");
  fakes[1].candidate = refusedAs(PlanStatus::kNoPath, "cannot stop");
  const Result<Plan> chosen = chooseFakes();
  ASSERT_FALSE(chosen.ok());
  EXPECT_EQ(chosen.status(), PlanStatus::kInfeasibleStart);
  EXPECT_EQ(chosen.error().message, "cannot leave; second: cannot stop");
}

TEST_F(MovingStartChooser, AnErrorOfTheRequestItselfIsReturnedAtOnce) {
  fakes[0].candidate = refusedAs(PlanStatus::kGoalInCollision, "goal too close");
  fakes[1].candidate = timedAs(1.0, 0.5, restPlan("second"));
  const Result<Plan> chosen = chooseFakes();
  ASSERT_FALSE(chosen.ok());
  EXPECT_EQ(chosen.status(), PlanStatus::kGoalInCollision);
  EXPECT_EQ(chosen.error().message, "goal too close");
  EXPECT_EQ(fakes[1].prepared, 0);
}

}  // namespace
}  // namespace cyber::planner

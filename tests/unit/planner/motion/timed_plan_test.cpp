// From candidate paths to a timed plan (timed_plan.hpp): columnsAgree on a bang-bang motion whose
// columns' errors are known in closed form, the shortest slowdown against that closed form and
// against what it must also meet (the predicate, the drive limits, its number of steps), timePaths
// and timedPath against the solver on the path stage's candidates, the reachability estimate, and
// the join of a stop before an onward plan.

#include "motion/timed_plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "math/weighted_norm.hpp"
#include "path/joined_path.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"
#include "timing/path_timing.hpp"
#include "timing/topp.hpp"

namespace cyber::planner {
namespace {

const RobotModel& model() { return test::referenceModel(); }
const MotionSettings& motion() { return model().planner.motion; }

// Rest to rest along the elevator alone over `length` m in `duration_s`: path acceleration +a up
// to halfway, -a after (b = 0, (2 L / T)^2, 0 at s = 0, L / 2, L).
Trajectory bangBang(double length, double duration_s) {
  auto line = std::make_shared<const StraightPath>(JointVector{{0.5, 1.6}}, JointVector{{1.0, 0.0}}, length);
  const double peak = 2.0 * length / duration_s;
  auto t =
      Trajectory::create(line, model().driveModel(HeldPieces{}), {0.0, 0.5 * length, length}, {0.0, peak * peak, 0.0});
  EXPECT_TRUE(t.ok());
  return std::move(t).value();
}

// The velocity column's error sampled every h from 0 (columnConsistency, relative to the fastest
// sample): the trapezoid across the switch at T/2 misses by 2 a h |phi - 1/2|, phi the switch's
// fraction of its step, and the fastest sample is the one nearest the switch, a (T/2 - min(phi,
// 1 - phi) h).
double bangBangVelocityError(double duration_s, double h) {
  const double phi = std::fmod(0.5 * duration_s / h, 1.0);
  return 2.0 * h * std::abs(phi - 0.5) / (0.5 * duration_s - std::min(phi, 1.0 - phi) * h);
}

// The smallest n with 1 / n within the velocity tolerance: stepped at T / (n + 1/2) the switch
// falls a quarter step from a sample and the velocity error is 1 / n (the position error,
// 0.75 / (n + 1/2)^2, is far inside its own tolerance).
int agreeingSteps() { return static_cast<int>(std::ceil(1.0 / motion().max_velocity_error)); }

TEST(TimedPlan, ColumnsAgreeWithinTheVelocityAndPositionTolerances) {
  const int n = agreeingSteps();
  const Trajectory t = bangBang(0.02, 0.05);
  const double duration = t.duration_s();
  ASSERT_NEAR(bangBangVelocityError(duration, duration / (n + 0.5)), 1.0 / n, 1e-12);
  EXPECT_NEAR(columnConsistency(t, duration / (n + 0.5)).velocity_error, 1.0 / n, 1e-9);
  EXPECT_TRUE(columnsAgree(motion(), t, duration / (n + 0.5)));
  EXPECT_FALSE(columnsAgree(motion(), t, duration / (n - 0.5)));
  // The position tolerance decides too: just below the position error at that step, refused.
  MotionSettings strict = motion();
  strict.max_position_error = 0.74 / ((n + 0.5) * (n + 0.5));
  EXPECT_FALSE(columnsAgree(strict, t, duration / (n + 0.5)));
  strict.max_position_error = 0.76 / ((n + 0.5) * (n + 0.5));
  EXPECT_TRUE(columnsAgree(strict, t, duration / (n + 0.5)));
  // Without a step, at the CSV's: a move of n + 1/2 steps agrees, one of n - 1/2 does not.
  EXPECT_TRUE(columnsAgree(motion(), bangBang(0.02, (n + 0.5) * motion().consistency_step_s)));
  EXPECT_FALSE(columnsAgree(motion(), bangBang(0.02, (n - 0.5) * motion().consistency_step_s)));
}

// Each step of the slowdown adds slower_step of the CSV's step to the duration; the first that the
// predicate accepts (within the limits) is taken, and none beyond `steps` is tried.
TEST(TimedPlan, TheShortestSlowdownIsTheFirstStepThePredicateAccepts) {
  const Trajectory t = bangBang(0.02, 0.05);
  const double step_s = motion().slower_step * motion().consistency_step_s;
  int asked = 0;
  const auto longer = [&](const Trajectory& slower) {
    ++asked;
    return slower.duration_s() > t.duration_s() + 3.5 * step_s;
  };
  const auto slowed = shortestSlowdown(model(), t, 10, longer);
  ASSERT_TRUE(slowed.has_value());
  EXPECT_NEAR(slowed->duration_s(), t.duration_s() + 4.0 * step_s, 1e-12);
  EXPECT_EQ(asked, 4);
  // The same path, slower: it ends where the original does.
  EXPECT_LT((slowed->sample(slowed->duration_s()).q - t.sample(t.duration_s()).q).norm(), 1e-12);
  asked = 0;
  EXPECT_FALSE(shortestSlowdown(model(), t, 3, longer).has_value());
  EXPECT_EQ(asked, 3);
  EXPECT_FALSE(shortestSlowdown(model(), t, 16, [](const Trajectory&) { return false; }).has_value());
  EXPECT_FALSE(shortestSlowdown(model(), t, 0, [](const Trajectory&) { return true; }).has_value());
  // Half a metre in 0.1 s needs far more than 12 V: no slowdown of a few milliseconds is within
  // the limits, whatever the predicate says.
  const Trajectory too_fast = bangBang(0.5, 0.1);
  EXPECT_FALSE(withinDriveLimits(too_fast, model().planner.topp));
  EXPECT_FALSE(shortestSlowdown(model(), too_fast, 16, [](const Trajectory&) { return true; }).has_value());
}

// A bang-bang of n - 1/2 steps disagrees at the CSV's step; the slowdown that makes its columns agree is
// the first whose switch, by the closed form above, lands where the trapezoid errs little enough.
TEST(TimedPlan, TheShortestSlowdownThatAgreesIsTheClosedFormsFirst) {
  const double h = motion().consistency_step_s;
  const Trajectory t = bangBang(0.02, (agreeingSteps() - 0.5) * h);
  ASSERT_FALSE(columnsAgree(motion(), t));
  ASSERT_TRUE(withinDriveLimits(t, model().planner.topp));
  const double step_s = motion().slower_step * h;
  int expected = -1;
  for (int i = 1; i <= motion().slower_steps && expected < 0; ++i) {
    if (bangBangVelocityError(t.duration_s() + i * step_s, h) <= motion().max_velocity_error) expected = i;
  }
  ASSERT_GT(expected, 0);
  const auto slowed = shortestSlowdown(model(), t, motion().slower_steps,
                                       [](const Trajectory& slower) { return columnsAgree(motion(), slower); });
  ASSERT_TRUE(slowed.has_value());
  EXPECT_NEAR(slowed->duration_s(), t.duration_s() + expected * step_s, 1e-12);
}

// The path stage's candidates for a public move, from rest and leaving along a velocity.
std::vector<PlannedPath> candidates(const test::PublicMove& move, const JointVector& v0 = JointVector::Zero(2)) {
  auto found = test::referencePathPlanner().candidates(move.from, move.to, move.pieces, v0);
  EXPECT_TRUE(found.ok()) << found.error().message;
  return found.ok() ? std::move(found).value() : std::vector<PlannedPath>{};
}

// Rest to rest, the first candidate whose columns agree is the solver's trajectory along it,
// with that candidate's waypoints, clearance and method.
TEST(TimedPlan, TimePathsIsTheSolversTrajectoryAlongTheFirstAgreeingCandidate) {
  const auto& move = test::publicMove("none:STOW->L4");
  const std::vector<PlannedPath> found = candidates(move);
  ASSERT_FALSE(found.empty());
  const auto plan = timePaths(model(), found, JointVector::Zero(2));
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  ToppSolver solver(model().planner.topp);
  size_t chosen = found.size();
  PlanMethod unrepaired = plan.value().method;
  unrepaired.repairs = 0;
  for (size_t i = 0; i < found.size(); ++i) {
    if (unrepaired == found[i].method) {
      chosen = i;
      break;
    }
  }
  ASSERT_LT(chosen, found.size()) << plan.value().method.name();
  const auto direct = solver.solve(found[chosen].path, model().driveModel(found[chosen].pieces), 0.0, nullptr);
  ASSERT_TRUE(direct.ok());
  if (plan.value().method.repairs == 0) {
    EXPECT_EQ(plan.value().trajectory->duration_s(), direct.value().duration_s());
  } else {
    EXPECT_GT(plan.value().trajectory->duration_s(), direct.value().duration_s());  // slowed or gentler
  }
  EXPECT_EQ(plan.value().waypoints, found[chosen].waypoints);
  EXPECT_EQ(plan.value().min_clearance_m, found[chosen].min_clearance_m);
  EXPECT_TRUE(columnsAgree(motion(), *plan.value().trajectory));
  EXPECT_EQ(&plan.value().trajectory->path(), found[chosen].path.get());
}

TEST(TimedPlan, TimePathsLeavesAlongTheStartVelocity) {
  const auto& move = test::publicMove("none:STOW->L4");
  const JointVector v0{{0.4, 1.0}};
  const auto plan = timePaths(model(), candidates(move, v0), v0);
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  EXPECT_LT((plan.value().trajectory->sample(0.0).qdot - v0).norm(), 1e-6);
  EXPECT_LT((plan.value().trajectory->sample(0.0).q - move.from).norm(), 1e-9);
}

TEST(TimedPlan, NoCandidateIsNoPlan) {
  const auto plan = timePaths(model(), {}, JointVector::Zero(2));
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.status(), inconsistentPlan().status());
  EXPECT_EQ(plan.error().message, inconsistentPlan().error().message);
  EXPECT_EQ(inconsistentPlan().status(), PlanStatus::kColumnsDisagree);
}

// timedPath is the path stage then timePaths: the same plan, and the path stage's refusals as they
// are.
TEST(TimedPlan, TimedPathIsThePathStageThenTimePaths) {
  const auto& move = test::publicMove("none:STOW->L4");
  const auto plan =
      timedPath(model(), test::referencePathPlanner(), move.from, move.to, move.pieces, JointVector::Zero(2));
  const auto expected = timePaths(model(), candidates(move), JointVector::Zero(2));
  ASSERT_TRUE(plan.ok() && expected.ok());
  EXPECT_EQ(plan.value().trajectory->duration_s(), expected.value().trajectory->duration_s());
  EXPECT_EQ(plan.value().method, expected.value().method);
  const JointVector outside{{model().range(0).max + 0.1, move.to.y()}};
  const auto refused =
      timedPath(model(), test::referencePathPlanner(), move.from, outside, move.pieces, JointVector::Zero(2));
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status(), PlanStatus::kGoalOutOfRange);
}

// The estimate of the first candidate from its start speed |v0|_Sigma; infinity without one.
TEST(TimedPlan, EstimatedSecondsAreTheFirstCandidatesReachabilityEstimate) {
  const auto& move = test::publicMove("none:STOW->L4");
  for (const JointVector& v0 : {JointVector::Zero(2).eval(), JointVector{{0.4, 1.0}}}) {
    const Result<std::vector<PlannedPath>> found = candidates(move, v0);
    const double speed = weightedNorm(v0, model().planner.metric);
    EXPECT_EQ(estimatedSeconds(model(), found, v0),
              estimateDuration(*found.value().front().path, model().driveModel(move.pieces), speed * speed,
                               motion().estimate_grid_points));
  }
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(
      estimatedSeconds(model(), Result<std::vector<PlannedPath>>(std::vector<PlannedPath>{}), JointVector::Zero(2)),
      inf);
  EXPECT_EQ(estimatedSeconds(model(), Result<std::vector<PlannedPath>>(PlanStatus::kNoPath), JointVector::Zero(2)),
            inf);
}

// A stop, then the plan from where it rests: one trajectory through the junction, the request's
// start before the onward waypoints, the method naming both; an onward refusal is passed on and
// a first part that does not end at rest is refused.
TEST(TimedPlan, JoinAfterPutsTheFirstPartBeforeTheOnwardPlan) {
  // Braking down the elevator into the STOW pose.
  const auto& move = test::publicMove("none:STOW->L4");
  const JointVector start = move.from + JointVector{{0.01, 0.0}};
  const auto stop_line = std::make_shared<const StraightPath>(start, JointVector{{-1.0, 0.0}}, 0.01);
  auto stop = Trajectory::create(stop_line, model().driveModel(HeldPieces{}), {0.0, 0.01}, {0.04, 0.0});
  ASSERT_TRUE(stop.ok());
  EXPECT_EQ(restOf(stop.value()), stop_line->at(0.01).q);
  const auto onward = timedPath(model(), test::referencePathPlanner(), restOf(stop.value()), move.to, HeldPieces{},
                                JointVector::Zero(2));
  ASSERT_TRUE(onward.ok()) << onward.error().message;
  PlanRequest request;
  request.start = start;
  request.goal = move.to;
  const auto joined = joinAfter(PlanMethod::kStoppedFirst, request, stop.value(), onward);
  ASSERT_TRUE(joined.ok()) << joined.error().message;
  EXPECT_NEAR(joined.value().trajectory->duration_s(),
              stop.value().duration_s() + onward.value().trajectory->duration_s(), 1e-12);
  ASSERT_EQ(joined.value().waypoints.size(), onward.value().waypoints.size() + 1);
  EXPECT_EQ(joined.value().waypoints.front(), start);
  PlanMethod stopped_first = onward.value().method;
  stopped_first.repairs |= PlanMethod::kStoppedFirst;
  EXPECT_EQ(joined.value().method, stopped_first);
  EXPECT_LT(joined.value().trajectory->sample(stop.value().duration_s()).qdot.norm(), 1e-12);

  const auto refused =
      joinAfter(PlanMethod::kStoppedFirst, request, stop.value(), Result<Plan>::failure(PlanStatus::kNoPath, "none"));
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status(), PlanStatus::kNoPath);
  EXPECT_EQ(refused.error().message, "none");
  auto still_moving = Trajectory::create(stop_line, model().driveModel(HeldPieces{}), {0.0, 0.01}, {0.04, 0.01});
  ASSERT_TRUE(still_moving.ok());
  const auto not_at_rest = joinAfter(PlanMethod::kStoppedFirst, request, still_moving.value(), onward);
  ASSERT_FALSE(not_at_rest.ok());
  EXPECT_EQ(not_at_rest.status(), PlanStatus::kInvalidInput);
}

}  // namespace
}  // namespace cyber::planner

// The fastest stop along the start velocity (fastest_stop.hpp, docs/moving-starts.md): it brakes
// from the first instant to rest within the limits, on about the shortest line that can stop it
// and in about the time an independent fine-grid reference takes on that line; its refusals
// (no velocity, a joint limit first, the clearance) and the stretched stop's closed form.

#include "motion/fastest_stop.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../timing/topp_fixtures.hpp"
#include "cyber/planner/trajectory.hpp"
#include "path/joined_path.hpp"
#include "reference_model.hpp"

namespace cyber::planner {
namespace {

// The reef scene, for fastestStop on its own.
struct Reef {
  explicit Reef(const std::string& pieces = "none")
      : world{model, model.scenes.front(), test::referencePieces(pieces)} {}
  const RobotModel& model = test::referenceModel();
  CollisionWorld world;
  ToppSolver solver{model.planner.topp};

  Result<Trajectory> stop(const JointVector& start, const JointVector& velocity) {
    return fastestStop(model, world, start, velocity, solver);
  }
};

// In the middle of the reef scene's free space, moving up and back.
const JointVector kStart{{1.0, 3.0}}, kVelocity{{0.8, -3.0}};

TEST(FastestStop, StopAlongTheVelocityBrakesFromTheFirstInstantAndEndsAtRest) {
  Reef reef;
  const auto stop = reef.stop(kStart, kVelocity);
  ASSERT_TRUE(stop.ok()) << stop.error().message;
  const Trajectory& t = stop.value();
  EXPECT_LT((t.sample(0.0).qdot - kVelocity).norm(), 1e-9);
  EXPECT_LT(t.sample(t.duration_s()).qdot.norm(), 1e-9);
  // Taken from the reachability profile, checked at the solver's step like the solver's results.
  EXPECT_TRUE(
      withinDriveLimits(t, reef.model.planner.topp.limit_check_step_s, reef.model.planner.topp.limit_check_tolerance));
  // Braking all the way: the speed only falls.
  double previous = t.bGrid().front();
  for (double b : t.bGrid()) {
    EXPECT_LE(b, previous * (1.0 + 1e-9));
    previous = b;
  }
}

// The line of the stop runs from the start along the velocity: every sample's position lies on
// it, and its velocity is parallel to v0.
TEST(FastestStop, StaysOnTheLineAlongTheVelocity) {
  Reef reef;
  const JointVector start{{0.6, 2.0}}, velocity{{-0.5, 2.0}};
  const auto stop = reef.stop(start, velocity);
  ASSERT_TRUE(stop.ok()) << stop.error().message;
  const JointVector along = velocity.normalized();
  for (int i = 0; i <= 50; ++i) {
    const TrajectorySample s = stop.value().sample(stop.value().duration_s() * i / 50);
    const JointVector moved = s.q - start;
    EXPECT_NEAR(moved.x() * along.y() - moved.y() * along.x(), 0.0, 1e-12) << "sample " << i;
    EXPECT_GE(moved.dot(along), -1e-12) << "sample " << i;
    EXPECT_NEAR(s.qdot.x() * along.y() - s.qdot.y() * along.x(), 0.0, 1e-9) << "sample " << i;
    EXPECT_GE(s.qdot.dot(along), -1e-9) << "sample " << i;
  }
}

// An independent reference (testing::FineReference, bisection on 2001 points) on the stop's own
// line takes about as long, and a line 5 % shorter cannot stop the start at all: the planner
// neither brakes more gently than the limits allow nor takes more room than it needs.
TEST(FastestStop, IsAboutTheFineReferencesTimeOnAboutTheShortestLine) {
  Reef reef;
  const JointVector metric = reef.model.planner.metric;
  for (const JointVector& velocity : {kVelocity, JointVector{{1.2, 0.0}}, JointVector{{0.0, 4.0}}}) {
    const JointVector& start = kStart;
    const auto stop = reef.stop(start, velocity);
    ASSERT_TRUE(stop.ok()) << stop.error().message;
    const double speed = std::sqrt(velocity.dot(metric.cwiseProduct(velocity)));
    const JointVector direction = velocity / speed;
    const double length = stop.value().path().length();
    const DriveModel drives = reef.model.driveModel(HeldPieces{});
    const testing::FineReference same(StraightPath(start, direction, length), drives.drive(0), drives.drive(1), 2001);
    const double reference_s = same.duration(speed * speed);
    ASSERT_FALSE(std::isnan(reference_s)) << "the reference cannot stop on the planner's line";
    EXPECT_NEAR(stop.value().duration_s(), reference_s, 0.02 * reference_s) << velocity.transpose();
    const testing::FineReference shorter(StraightPath(start, direction, 0.95 * length), drives.drive(0),
                                         drives.drive(1), 2001);
    EXPECT_TRUE(std::isnan(shorter.duration(speed * speed))) << velocity.transpose();
  }
}

TEST(FastestStop, NoStopIsOfferedIntoAJointLimit) {
  Reef reef;
  const JointVector start{{1.999, 3.0}}, velocity{{2.5, 0.0}};
  const auto stop = reef.stop(start, velocity);
  ASSERT_FALSE(stop.ok());
  EXPECT_EQ(stop.status(), PlanStatus::kInfeasibleStart);
  EXPECT_EQ(reef.stop(start, JointVector::Zero(2)).status(), PlanStatus::kInvalidInput);
  // At the limit already, moving out of the range: no room at all.
  const double top = reef.model.range(0).max;
  EXPECT_EQ(reef.stop(JointVector{{top, 3.0}}, (JointVector{{0.1, 0.0}})).status(), PlanStatus::kInfeasibleStart);
}

TEST(FastestStop, AVelocityThatIsNotFiniteIsInvalidInput) {
  Reef reef;
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const JointVector& velocity : {JointVector{{nan, 1.0}}, JointVector{{0.0, inf}}, JointVector{{-inf, 0.0}}}) {
    const auto stop = reef.stop(kStart, velocity);
    ASSERT_FALSE(stop.ok()) << velocity.transpose();
    EXPECT_EQ(stop.status(), PlanStatus::kInvalidInput) << velocity.transpose();
    EXPECT_EQ(stop.error().message, "no velocity to stop from");
  }
}

// Next to the reef's L4 trunk with coral held, moving into it (moving_start_test.cpp's refusal):
// the stop itself would come closer than the clearance.
const JointVector kNearTheTrunk{{1.4124, 5.6042}}, kIntoTheTrunk{{1.4675, 3.1783}};

TEST(FastestStop, BrakingIntoAnObstacleIsRefused) {
  Reef reef("coral");
  const auto stop = reef.stop(kNearTheTrunk, kIntoTheTrunk);
  ASSERT_FALSE(stop.ok());
  EXPECT_EQ(stop.status(), PlanStatus::kClearanceNotMet);
  EXPECT_EQ(stop.error().message, "braking along the start velocity comes closer than the clearance");
  // Moving away from it, the same start can stop.
  EXPECT_TRUE(reef.stop(kNearTheTrunk, -kIntoTheTrunk).ok());
}

// b(s) becomes b(s / factor): the same speeds `factor` times further along, so the duration grows
// by exactly that factor and each velocity at time factor t is the stop's at t (decelerations
// shrink by 1 / factor).
TEST(FastestStop, AStretchedStopIsTheSameStopSlowerByItsFactor) {
  Reef reef;
  const auto stop = reef.stop(kStart, kVelocity);
  ASSERT_TRUE(stop.ok()) << stop.error().message;
  const Trajectory& fast = stop.value();
  for (const double factor : {1.0, 1.1, 1.5}) {
    const auto stretched = stretchedStop(reef.model, reef.world, fast, factor);
    ASSERT_TRUE(stretched.ok()) << stretched.error().message;
    const Trajectory& slow = stretched.value();
    EXPECT_NEAR(slow.duration_s(), factor * fast.duration_s(), 1e-12 * fast.duration_s()) << factor;
    EXPECT_GE(slow.duration_s(), fast.duration_s()) << factor;
    EXPECT_LT(
        (slow.sample(slow.duration_s()).q - (kStart + factor * (fast.sample(fast.duration_s()).q - kStart))).norm(),
        1e-12)
        << factor;
    // Mid-interval, away from the jumps of acceleration at the grid's times.
    const std::vector<double>& times = fast.tGrid();
    for (size_t k = 0; k + 1 < times.size(); k += 7) {
      const double t = 0.5 * (times[k] + times[k + 1]);
      const TrajectorySample a = fast.sample(t), b = slow.sample(factor * t);
      EXPECT_LT((b.qdot - a.qdot).norm(), 1e-9 * (1.0 + a.qdot.norm())) << factor << " at " << t;
      EXPECT_LT((b.qddot - a.qddot / factor).norm(), 1e-6 * (1.0 + a.qddot.norm())) << factor << " at " << t;
    }
    EXPECT_TRUE(withinDriveLimits(slow, reef.model.planner.topp)) << factor;
  }
}

TEST(FastestStop, AStretchedStopOutOfTheRangeOrIntoAnObstacleIsRefused) {
  Reef reef;
  const auto stop = reef.stop(JointVector{{1.9, 3.0}}, JointVector{{0.5, 0.0}});
  ASSERT_TRUE(stop.ok()) << stop.error().message;
  const double room = reef.model.range(0).max - 1.9;
  const double factor = 1.01 * room / (stop.value().sample(stop.value().duration_s()).q.x() - 1.9);
  const auto out = stretchedStop(reef.model, reef.world, stop.value(), factor);
  ASSERT_FALSE(out.ok());
  EXPECT_EQ(out.status(), PlanStatus::kInfeasibleStart);

  // The stop into the L4 trunk, planned where there is no trunk (the open scene), then judged in
  // the reef: its line comes closer than the clearance.
  Reef coral("coral");
  const auto into = fastestStop(coral.model, CollisionWorld(coral.model, coral.model.scenes[1], coral.world.pieces()),
                                kNearTheTrunk, kIntoTheTrunk, coral.solver);
  ASSERT_TRUE(into.ok()) << into.error().message;
  const auto stretched = stretchedStop(coral.model, coral.world, into.value(), 1.0);
  ASSERT_FALSE(stretched.ok());
  EXPECT_EQ(stretched.status(), PlanStatus::kClearanceNotMet);
}

}  // namespace
}  // namespace cyber::planner

// The synchronised candidate (synchronised_path.hpp): every path it returns keeps the clearance,
// starts and ends exactly at the move's poses and is no faster than its slower joint alone (no
// path can be); it finds the slower joint's own time on the public moves that allow it, and
// returns nothing where it cannot help.

#include "path/synchronised_path.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "path/joined_path.hpp"
#include "path/path_clearance.hpp"
#include "path/path_planner.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"
#include "timing/path_timing.hpp"

namespace cyber::planner {
namespace {

constexpr double kNoBound = std::numeric_limits<double>::infinity();

const RobotModel& model() { return test::referenceModel(); }
const PathPlanner& planner() { return test::referencePathPlanner(); }

// The slower joint moving alone, timed independently of the search: a straight one-joint path on
// a fine grid.
double slowerJointAloneS(const JointVector& from, const JointVector& to) {
  const DriveModel drives = model().driveModel({});
  double slower = 0.0;
  for (int j = 0; j < 2; ++j) {
    JointVector direction = JointVector::Zero(2);
    direction[j] = to[j] > from[j] ? 1.0 : -1.0;
    slower =
        std::max(slower, estimateDuration(StraightPath(from, direction, std::abs(to[j] - from[j])), drives, 0.0, 1000));
  }
  return slower;
}

void expectSound(const SynchronisedPath& found, const JointVector& from, const JointVector& to,
                 const CollisionWorld& world) {
  EXPECT_EQ(found.waypoints.front(), from);
  EXPECT_EQ(found.waypoints.back(), to);
  EXPECT_EQ(found.path.at(0.0).q, from);
  EXPECT_NEAR((found.path.at(found.path.length()).q - to).norm(), 0.0, 1e-12);
  EXPECT_TRUE(checkPath(found.path, world, model(), model().clearance_m).ok());
  EXPECT_GE(found.min_clearance_m, model().clearance_m);
  EXPECT_NEAR(found.slower_alone_s, slowerJointAloneS(from, to), 2e-3 * found.slower_alone_s);
  // The coarse estimate may be a little optimistic between its grid points, not more.
  EXPECT_GE(found.estimate_s, 0.98 * found.slower_alone_s);
}

TEST(SynchronisedPath, OnThePublicMovesEveryPathIsSoundAndSomeReachTheSlowerJointsOwnTime) {
  int found_count = 0, at_the_bound = 0;
  for (const test::PublicMove& move : test::publicMoves()) {
    if (!planner().candidates(move.from, move.to, move.pieces).ok()) continue;  // unreachable
    SCOPED_TRACE(move.label);
    const CollisionWorld& world = planner().world(move.pieces);
    const auto found = synchronisedPath(move.from, move.to, world, model(), kNoBound);
    if (!found) continue;
    ++found_count;
    expectSound(*found, move.from, move.to, world);
    at_the_bound += found->estimate_s <= 1.025 * found->slower_alone_s ? 1 : 0;
  }
  // Measured: 70 of the 126 reachable moves have one, 56 of them within 2.5 % of the bound.
  EXPECT_GE(found_count, 60);
  EXPECT_GE(at_the_bound, 45);
}

TEST(SynchronisedPath, IntakeToStowRunsTheSlowerJointAtItsOwnTime) {
  const JointVector from{{0.58, 2.97}}, to{{0.2, 1.57}};
  const auto found = synchronisedPath(from, to, planner().world(HeldPieces{}), model(), kNoBound);
  ASSERT_TRUE(found.has_value());
  expectSound(*found, from, to, planner().world(HeldPieces{}));
  EXPECT_LE(found->estimate_s, 1.025 * found->slower_alone_s);
}

TEST(SynchronisedPath, NothingWhenTheBoundCannotBeBeatenOrAJointStays) {
  const JointVector from{{0.58, 2.97}}, to{{0.2, 1.57}};
  const CollisionWorld& world = planner().world(HeldPieces{});
  const auto free = synchronisedPath(from, to, world, model(), kNoBound);
  ASSERT_TRUE(free.has_value());
  EXPECT_FALSE(synchronisedPath(from, to, world, model(), 0.999 * free->slower_alone_s).has_value());
  EXPECT_FALSE(synchronisedPath(from, (JointVector{{0.58, 1.57}}), world, model(), kNoBound).has_value());
  EXPECT_FALSE(synchronisedPath(from, (JointVector{{0.2, 2.97}}), world, model(), kNoBound).has_value());
}

TEST(SynchronisedPath, NothingWhereEveryPairingHitsTheReef) {
  // none L4 -> PROCESSOR: the arm must swing round the reef's posts while the elevator descends;
  // no pairing of the two monotone profiles keeps the clearance.
  EXPECT_FALSE(synchronisedPath(JointVector{{1.97, 5.17}}, (JointVector{{0.16, 0.1}}), planner().world(HeldPieces{}),
                                model(), kNoBound)
                   .has_value());
}

TEST(SynchronisedPath, SeededRandomFreeMovesAreSound) {
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<double> elevator(model().range(0).min, model().range(0).max);
  std::uniform_real_distribution<double> arm(model().range(1).min, model().range(1).max);
  const CollisionWorld& world = planner().world(HeldPieces{});
  auto free_pose = [&] {
    for (;;) {
      const double t = elevator(rng);
      const double theta = arm(rng);  // sequenced: the order of two draws in one call is unspecified
      const JointVector q{{t, theta}};
      if (world.distance(q).value >= model().clearance_m) return q;
    }
  };
  int found_count = 0;
  for (int i = 0; i < 120; ++i) {
    const JointVector from = free_pose();
    const JointVector to = free_pose();
    SCOPED_TRACE(::testing::Message() << "move " << i);
    const auto found = synchronisedPath(from, to, world, model(), kNoBound);
    if (!found) continue;
    ++found_count;
    expectSound(*found, from, to, world);
  }
  EXPECT_GE(found_count, 70);  // measured: 87 of 120
}

}  // namespace
}  // namespace cyber::planner

// The shape search against the reachability time (path_shaping.hpp) on the public moves: it never
// returns a slower or less clear path, keeps the fixed knots, and finds a faster shape where the
// smoothed search path keeps needlessly far from the obstacles.

#include "path/path_shaping.hpp"

#include <array>
#include <span>
#include <string>

#include <gtest/gtest.h>

#include "path/path_clearance.hpp"
#include "path/path_planner.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"
#include "timing/path_timing.hpp"

namespace cyber::planner {
namespace {

const RobotModel& model() { return test::referenceModel(); }

const PathPlanner& planner() { return test::referencePathPlanner(); }

// Both searches on the search's own smoothed path of every public move that has one: never
// slower nor less clear than their input, the fixed knots kept. Returns how many moves were
// shaped and how many of them became 3 % faster.
template <class Settings>
using ShapeSearch = ShapedPath (*)(std::span<const JointVector>, int, const JointVector&, const CollisionWorld&,
                                   const RobotModel&, double, const Settings&);

template <class Settings>
std::array<int, 2> checkOnPublicMoves(ShapeSearch<Settings> search, const Settings& settings) {
  const int max_evaluations = settings.max_evaluations, grid_points = settings.grid_points;
  const DriveModel drives = model().driveModel({});
  int shaped = 0, much_faster = 0, checked = 0;
  for (const test::PublicMove& move : test::publicMoves()) {
    // The search's own smoothed path alone, not yet chosen for time.
    auto found = planner().candidates(move.from, move.to, move.pieces, JointVector::Zero(2), PathAlternatives::kNone);
    if (!found || found.value().front().direct) continue;
    const PlannedPath& path = found.value().front();
    const CollisionWorld& world = planner().world(move.pieces);
    const ShapedPath result = search(path.waypoints, 1, JointVector::Zero(2), world, model(), 0.0, settings);
    ++checked;
    const double before_s = estimateDuration(*path.path, drives, 0.0, grid_points);
    EXPECT_LE(result.evaluations, max_evaluations) << move.label;
    EXPECT_EQ(result.waypoints.size(), path.waypoints.size()) << move.label;
    if (result.waypoints.size() != path.waypoints.size()) continue;
    EXPECT_EQ(result.waypoints.front(), path.waypoints.front()) << move.label;
    EXPECT_EQ(result.waypoints.back(), path.waypoints.back()) << move.label;
    EXPECT_NEAR(result.estimate_s, estimateDuration(result.path, drives, 0.0, grid_points), 1e-12);
    if (result.improvements == 0) {
      EXPECT_EQ(result.waypoints, path.waypoints) << move.label;
      EXPECT_DOUBLE_EQ(result.estimate_s, before_s) << move.label;
      continue;
    }
    ++shaped;
    EXPECT_LT(result.estimate_s, before_s) << move.label;
    if (result.estimate_s < 0.97 * before_s) ++much_faster;
    // Clear and inside the limits, checked again here at a finer spacing than the planner's.
    const ClearanceCheck check = checkPath(result.path, world, model(), model().clearance_m, 0.25 * kDenseCheckStep);
    EXPECT_TRUE(check.ok()) << move.label << ": " << check.min_distance_m << " m at s = " << check.at_s;
    EXPECT_NEAR(result.min_clearance_m, check.min_distance_m, 1e-3) << move.label;
  }
  EXPECT_GT(checked, 60);
  return {shaped, much_faster};
}

TEST(ShapeForTime, NeverSlowerNorCloserAndKeepsTheEnds) {
  const auto [shaped, much_faster] = checkOnPublicMoves(shapeForTime, ShapeSearchSettings{});
  EXPECT_GT(shaped, 30) << "the search finds faster shapes on many moves";
  EXPECT_GT(much_faster, 5);
}

TEST(RefineShapeForTime, NeverSlowerNorCloserAndKeepsTheEnds) {
  const auto [shaped, much_faster] = checkOnPublicMoves(refineShapeForTime, ShapeRefinementSettings{});
  EXPECT_GT(shaped, 30);
  EXPECT_GT(much_faster, 15) << "its budget is spent where it gains";
}

// coral INTAKE -> L2: the planner's shortcut path touches the clearance where the arm swings past
// the reef, and every bump over the whole path moves that place into it. Held still there, the
// rest of the path can still be made faster.
TEST(RefineShapeForTime, HoldingTheTouchedPlaceStillFindsAFasterShape) {
  const test::PublicMove& move = test::publicMove("coral:INTAKE->L2");
  auto found = planner().candidates(move.from, move.to, move.pieces, JointVector::Zero(2));
  ASSERT_TRUE(found.ok());
  const PlannedPath* shortcut = nullptr;
  for (const PlannedPath& c : found.value()) {
    if (c.method.strategy == "shortcut") shortcut = &c;
  }
  ASSERT_NE(shortcut, nullptr);
  const CollisionWorld& world = planner().world(move.pieces);
  // From the first search's shape, as the planner refines it.
  const std::vector<JointVector> start =
      shapeForTime(shortcut->waypoints, 1, JointVector::Zero(2), world, model(), 0.0, ShapeSearchSettings{}).waypoints;
  ShapeRefinementSettings held;
  ShapeRefinementSettings whole = held;
  whole.pin_width = 0.0;
  const ShapedPath with = refineShapeForTime(start, 1, JointVector::Zero(2), world, model(), 0.0, held);
  const ShapedPath without = refineShapeForTime(start, 1, JointVector::Zero(2), world, model(), 0.0, whole);
  EXPECT_LT(with.estimate_s, 0.995 * without.estimate_s)
      << "held " << with.estimate_s << " s, whole bumps only " << without.estimate_s << " s";
}

TEST(ShapeForTime, WithoutFreeKnotsOrBumpsReturnsTheInput) {
  const CollisionWorld& world = planner().world(HeldPieces{});
  const std::vector<JointVector> segment{JointVector{{0.2, 1.57}}, JointVector{{0.3, 1.7}}};
  const ShapedPath two = shapeForTime(segment, 1, JointVector::Zero(2), world, model(), 0.0, ShapeSearchSettings{});
  EXPECT_EQ(two.improvements, 0);
  EXPECT_EQ(two.evaluations, 0);
  EXPECT_EQ(two.waypoints, segment);
  const std::vector<JointVector> bent{JointVector{{0.2, 1.57}}, JointVector{{0.5, 1.9}}, JointVector{{0.6, 2.9}}};
  ShapeSearchSettings none;
  none.bumps = 0;
  const ShapedPath unchanged = shapeForTime(bent, 1, JointVector::Zero(2), world, model(), 0.0, none);
  EXPECT_EQ(unchanged.improvements, 0);
  EXPECT_EQ(unchanged.waypoints, bent);
}

}  // namespace
}  // namespace cyber::planner

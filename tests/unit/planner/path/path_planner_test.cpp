// The path stage on the reference robot: every public move gives a path that keeps the clearance
// (checked independently at <= 1 mm spacing with the pieces held), and every bad input gives its
// typed error.

#include "path/path_planner.hpp"

#include <array>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "timing/path_timing.hpp"

#include "free_space_components.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"

namespace cyber::planner {
namespace {

const RobotModel& model() { return test::referenceModel(); }

const PathPlanner& planner() { return test::referencePathPlanner(); }

// The reference robot with the code's default smoothing settings (the tuned values recommended
// for the configuration file).
const PathPlanner& defaultSmoothingPlanner() {
  static const PathPlanner p = [] {
    RobotModel m = model();
    m.planner.smoothing = SmoothingSettings{};
    return PathPlanner(m, m.scenes.front());
  }();
  return p;
}

// Distances above this are not needed exactly (the dense check only looks at the closest part).
constexpr double kDenseCutoff = 0.1;

struct DenseCheck {
  double min_distance = std::numeric_limits<double>::infinity();  // exact when below kDenseCutoff
  double max_step = 0.0;  // largest max(|dt|, |dtheta|) between consecutive samples
  bool within_limits = true;
};

// Uniform samples in s, fine enough that consecutive samples differ by <= 1 mm / 1 mrad.
DenseCheck denseCheck(const GeometricPath& path, const CollisionWorld& world) {
  DenseCheck out;
  double fastest = 0.0;
  for (int i = 0; i <= 1000; ++i)
    fastest = std::max(fastest, path.at(path.length() * i / 1000.0).dq_ds.cwiseAbs().maxCoeff());
  const int samples = std::max(1, static_cast<int>(std::ceil(path.length() * fastest * 1.25 / 1e-3)));
  JointVector previous = path.at(0.0).q;
  for (int i = 0; i <= samples; ++i) {
    const JointVector q = path.at(path.length() * i / samples).q;
    out.max_step = std::max(out.max_step, (q - previous).cwiseAbs().maxCoeff());
    out.min_distance = std::min(out.min_distance, world.distance(q, kDenseCutoff).value);
    out.within_limits = out.within_limits && model().withinLimits(q);
    previous = q;
  }
  return out;
}

// Whether no path keeping the clearance joins the poses (a proof of "no path").
bool separated(HeldPieces pieces, const JointVector& a, const JointVector& b) {
  return test::provedSeparated(model(), planner().world(pieces), a, b);
}

void checkEveryPublicMove(const PathPlanner& planner) {
  const auto& moves = test::publicMoves();
  ASSERT_EQ(moves.size(), 144U);
  int searched = 0, planned_count = 0, disconnected = 0;
  for (const test::PublicMove& move : moves) {
    const auto result = planner.plan(move.from, move.to, move.pieces);
    if (!result.ok()) {
      // Only a goal in another component of the free space may be refused.
      ASSERT_EQ(result.status(), PlanStatus::kNoPath) << move.label << ": " << result.error().message;
      EXPECT_TRUE(separated(move.pieces, move.from, move.to)) << move.label;
      ++disconnected;
      continue;
    }
    ++planned_count;
    const PlannedPath& planned = result.value();
    const GeometricPath& path = *planned.path;
    EXPECT_NEAR((path.at(0.0).q - move.from).norm(), 0.0, 1e-12) << move.label;
    EXPECT_NEAR((path.at(path.length()).q - move.to).norm(), 0.0, 1e-12) << move.label;
    EXPECT_EQ(planned.waypoints.front(), move.from);
    EXPECT_EQ(planned.waypoints.back(), move.to);
    EXPECT_EQ(planned.search_waypoints.front(), move.from);
    EXPECT_EQ(planned.search_waypoints.back(), move.to);
    const DenseCheck check = denseCheck(path, planner.world(move.pieces));
    EXPECT_LE(check.max_step, 1e-3) << move.label;
    EXPECT_GE(check.min_distance, model().clearance_m) << move.label << " via " << planned.method.name();
    EXPECT_TRUE(check.within_limits) << move.label;
    // The planner's own minimum (certified steps, then a dense scan around the closest sample)
    // agrees with the dense one to within the sampling.
    EXPECT_GE(planned.min_clearance_m, model().clearance_m) << move.label;
    if (check.min_distance < kDenseCutoff) {
      EXPECT_NEAR(planned.min_clearance_m, check.min_distance, 2e-3) << move.label;
    } else {
      EXPECT_GE(planned.min_clearance_m, kDenseCutoff - 2e-3) << move.label;
    }
    if (!planned.direct) ++searched;
  }
  EXPECT_GT(searched, 20) << "the public moves exercise the grid search";
  // With the reference geometry, coral at L4 and algae at HOLD_HIGH sit in pockets of the free
  // space that no other pose of their set reaches (the held piece cannot swing past the reef):
  // 2 x 6 coral moves and 2 x 3 algae moves.
  EXPECT_EQ(disconnected, 18);
  EXPECT_EQ(planned_count, 126);
}

TEST(PathPlanner, EveryPublicMoveKeepsTheClearanceOrProvablyHasNoPath) { checkEveryPublicMove(planner()); }

TEST(PathPlanner, EveryPublicMoveWithTheDefaultSmoothingSettings) { checkEveryPublicMove(defaultSmoothingPlanner()); }

// A direct path gets a shaped candidate first when that is estimated faster and clear (on the
// public moves between INTAKE and STOW, for one), and a synchronised one before that when it is
// faster still; the others keep their one straight candidate.
TEST(PathPlanner, DirectPathsAreShapedForTimeWhenThatIsFaster) {
  const DriveModel drives = model().driveModel({});
  int shaped = 0, straight = 0, synchronised = 0;
  for (const test::PublicMove& move : test::publicMoves()) {
    const auto found = planner().candidates(move.from, move.to, move.pieces);
    if (!found.ok() || !found.value().back().direct) continue;
    const std::vector<PlannedPath>& all = found.value();
    EXPECT_EQ(all.back().method.smoothing, PlanMethod::Smoothing::kStraight) << move.label;
    if (all.size() == 1) {
      ++straight;
      continue;
    }
    ASSERT_LE(all.size(), 3U) << move.label;
    for (size_t i = 0; i + 1 < all.size(); ++i) {
      const PlanMethod& method = all[i].method;
      const bool shaped_straight =
          method.smoothing == PlanMethod::Smoothing::kShaped && method.shaped_from == PlanMethod::kFirstPath;
      const bool joints = method.smoothing == PlanMethod::Smoothing::kSynchronised;
      EXPECT_TRUE(shaped_straight || joints) << move.label << ": " << method.name();
      shaped += shaped_straight ? 1 : 0;
      synchronised += joints ? 1 : 0;
      EXPECT_LT(estimateDuration(*all[i].path, drives, 0.0, 100), estimateDuration(*all[i + 1].path, drives, 0.0, 100))
          << move.label;
      EXPECT_GE(all[i].min_clearance_m, model().clearance_m) << move.label;
    }
  }
  EXPECT_GE(shaped, 6);
  EXPECT_GE(synchronised, 3);  // INTAKE -> STOW with each piece
  EXPECT_GT(straight, 30);
}

TEST(PathPlanner, ExactStartAndGoalAreKeptOffTheGrid) {
  // Poses between grid nodes: the path starts and ends exactly there.
  const JointVector start{{0.2137, 1.5731}}, goal{{0.7813, 6.0871}};
  ASSERT_FALSE(separated(test::referencePieces("coral"), start, goal));
  const auto result = planner().plan(start, goal, test::referencePieces("coral"));
  ASSERT_TRUE(result.ok()) << result.error().message;
  EXPECT_EQ(result.value().path->at(0.0).q, start);
  EXPECT_NEAR((result.value().path->at(result.value().path->length()).q - goal).norm(), 0.0, 1e-12);
}

TEST(PathPlanner, ZeroLengthMoveIsATrivialPath) {
  const JointVector q{{0.2, 1.57}};
  const auto result = planner().plan(q, q, HeldPieces{});
  ASSERT_TRUE(result.ok()) << result.error().message;
  const GeometricPath& path = *result.value().path;
  EXPECT_EQ(path.length(), 0.0);
  const PathPoint p = path.at(0.0);
  EXPECT_EQ(p.q, q);
  EXPECT_EQ(p.dq_ds, JointVector::Zero(2));
  EXPECT_EQ(p.d2q_ds2, JointVector::Zero(2));
}

TEST(PathPlanner, VeryShortMovesAreValid) {
  for (double step : {1e-8, 1e-6, 1e-4, 1e-2}) {
    const JointVector start{{0.58, 2.97}}, goal = start + JointVector{{step, -step}};
    const auto result = planner().plan(start, goal, test::referencePieces("coral+algae"));
    ASSERT_TRUE(result.ok()) << step << ": " << result.error().message;
    const GeometricPath& path = *result.value().path;
    EXPECT_GT(path.length(), 0.0);
    EXPECT_NEAR((path.at(path.length()).q - goal).norm(), 0.0, 1e-12);
    EXPECT_TRUE(path.at(0.5 * path.length()).q.allFinite());
  }
}

TEST(PathPlanner, BadInputsGiveTypedErrors) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const JointVector ok_start{{0.2, 1.57}}, ok_goal{{1.93, 1.71}};
  const HeldPieces none{};
  EXPECT_EQ(planner().plan(JointVector{{nan, 1.0}}, ok_goal, none).status(), PlanStatus::kInvalidInput);
  EXPECT_EQ(planner().plan(ok_start, (JointVector{{1.0, inf}}), none).status(), PlanStatus::kInvalidInput);
  EXPECT_EQ(planner().plan(ok_start, ok_goal, none, (JointVector{{nan, 0.0}})).status(), PlanStatus::kInvalidInput);
  EXPECT_EQ(planner().plan(JointVector{{-0.1, 1.57}}, ok_goal, none).status(), PlanStatus::kStartOutOfRange);
  EXPECT_EQ(planner().plan(JointVector{{0.2, 6.2}}, ok_goal, none).status(), PlanStatus::kStartOutOfRange);
  EXPECT_EQ(planner().plan(ok_start, (JointVector{{2.01, 1.57}}), none).status(), PlanStatus::kGoalOutOfRange);
  EXPECT_EQ(planner().plan(ok_start, (JointVector{{1.0, -0.01}}), none).status(), PlanStatus::kGoalOutOfRange);
  // Arm pointing straight down at the bottom of the rail: through the floor / drivetrain.
  const JointVector in_floor{{0.0, 4.71}};
  ASSERT_LT(planner().world(none).distance(in_floor).value, model().clearance_m);
  const auto start_hit = planner().plan(in_floor, ok_goal, none);
  EXPECT_EQ(start_hit.status(), PlanStatus::kStartInCollision);
  EXPECT_FALSE(start_hit.error().message.empty());
  EXPECT_EQ(planner().plan(ok_start, in_floor, none).status(), PlanStatus::kGoalInCollision);
  // Held pieces count: a pose that is free for the bare arm but not with algae.
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> t(0.0, 2.0), th(0.0, 6.1);
  int found = 0;
  for (int i = 0; i < 5000 && found < 5; ++i) {
    const JointVector q{{t(rng), th(rng)}};
    if (planner().world(none).distance(q).value < 0.1) continue;
    if (planner().world(test::referencePieces("algae")).distance(q).value >= model().clearance_m) continue;
    ++found;
    EXPECT_EQ(planner().plan(q, ok_goal, test::referencePieces("algae")).status(), PlanStatus::kStartInCollision);
    EXPECT_EQ(planner().plan(ok_start, q, test::referencePieces("algae")).status(), PlanStatus::kGoalInCollision);
  }
  EXPECT_EQ(found, 5);
}

TEST(PathPlanner, CagedGoalIsNoPath) {
  // Two bars just above and below the arm pointing forward at t = 1: the pose keeps the
  // clearance, but any motion out of it comes closer than the clearance.
  const Point2 pivot = linkFrames(model().joints, JointVector{{1.0, 0.0}})[1].origin_m;
  auto box = [](double x0, double y0, double x1, double y1) {
    return ConvexPolygon::fromVertices({Point2(x0, y0), Point2(x1, y0), Point2(x1, y1), Point2(x0, y1)}).value();
  };
  Scene scene{"cage", {}, {}, {}};
  scene.obstacles.push_back({"floor", box(-2.0, -1.0, 2.0, 0.0)});
  scene.obstacles.push_back({"upper bar", box(-0.1, pivot.y() + 0.15, 0.3, pivot.y() + 0.2)});
  scene.obstacles.push_back({"lower bar", box(-0.1, pivot.y() - 0.2, 0.3, pivot.y() - 0.15)});
  RobotModel caged = model();
  caged.scenes = {scene};
  const PathPlanner cage(caged, scene);
  const JointVector inside{{1.0, 0.0}}, outside{{0.2, 1.57}};
  ASSERT_GE(cage.world(HeldPieces{}).distance(inside).value, caged.clearance_m);
  ASSERT_GE(cage.world(HeldPieces{}).distance(outside).value, caged.clearance_m);
  const auto in = cage.plan(outside, inside, HeldPieces{});
  EXPECT_EQ(in.status(), PlanStatus::kNoPath) << (in.ok() ? "found a path" : in.error().message);
  const auto out = cage.plan(inside, outside, HeldPieces{});
  EXPECT_EQ(out.status(), PlanStatus::kNoPath) << (out.ok() ? "found a path" : out.error().message);
  // The rest of the scene is open: other moves still work.
  const auto open = cage.plan(outside, JointVector{{0.6, 3.0}}, HeldPieces{});
  EXPECT_TRUE(open.ok()) << open.error().message;
  // A moving start searches from its lead-in's end; the refusal quotes the start asked for, then
  // that end (the lead-in's end alone is a start the user never asked for).
  const auto moving = cage.plan(outside, inside, HeldPieces{}, JointVector{{0.0, 1.0}});
  ASSERT_EQ(moving.status(), PlanStatus::kNoPath) << (moving.ok() ? "found a path" : "");
  EXPECT_EQ(
      moving.error().message.rfind("the goal (1.0000 m, 0.0000 rad) cannot be reached from (0.2000 m, 1.5700 rad) "
                                   "(after its lead-in to (",
                                   0),
      0U)
      << moving.error().message;
}

// A band of offsets searches a grid of the field elements swept across the band, which blocks the
// nodes near a start a few centimetres from the reef. The move plans at its exact offset all the
// same (the exact offset's own grid, built for the request), as it does at offset 0 (a move of
// near_field_element_starts_test.cpp that the band's grid alone refused; docs/algorithm.md,
// "2.1 Grid and potential").
TEST(PathPlanner, ABandsGridWithNoPathGivesWayToTheExactOffsetsGrid) {
  const Scene& reef = model().scenes.front();
  const JointRange band{0.06, 0.12};
  const double offset = 0.107967;
  ASSERT_GE(offset, reef.offset_range_m.min);
  ASSERT_LE(offset, reef.offset_range_m.max);
  const PathPlanner shifted = PathPlanner(model(), reef, band).atOffset(offset);
  const JointVector start{{1.42206946, 0.0366818841}}, goal{{1.93, 1.71}};  // near l2_branch; NET
  const CollisionWorld& world = shifted.world(HeldPieces{});
  ASSERT_GE(world.distance(start).value, model().clearance_m);
  ASSERT_LT(world.distance(start).value, model().clearance_m + band.max - band.min);
  // The band's grid is blocked all around the start.
  const CSpaceGrid& banded = shifted.grid(HeldPieces{});
  const int corner = banded.lowerCorner(start);
  for (int di = 0; di <= 1; ++di) {
    for (int dj = 0; dj <= 1; ++dj) {
      EXPECT_TRUE(banded.blocked(banded.cell(banded.firstIndex(corner) + di, banded.secondIndex(corner) + dj)));
    }
  }
  const auto planned = shifted.plan(start, goal, HeldPieces{});
  ASSERT_TRUE(planned.ok()) << planned.error().message;
  EXPECT_TRUE(planned.value().exact_offset_grid);
  const DenseCheck check = denseCheck(*planned.value().path, world);
  EXPECT_GE(check.min_distance, model().clearance_m);
  EXPECT_TRUE(check.within_limits);
  // So does a moving start, which searches from its lead-in's end.
  const auto moving = shifted.plan(start, goal, HeldPieces{}, (JointVector{{0.2, 0.0}}));
  ASSERT_TRUE(moving.ok()) << moving.error().message;
  EXPECT_TRUE(moving.value().lead_in);
  EXPECT_TRUE(moving.value().exact_offset_grid);
  EXPECT_GE(denseCheck(*moving.value().path, world).min_distance, model().clearance_m);
  // A move the band's grid serves keeps to it.
  const auto open = shifted.plan(JointVector{{0.49, 6.07}}, (JointVector{{1.97, 5.17}}), HeldPieces{});  // L1 -> L4
  ASSERT_TRUE(open.ok()) << open.error().message;
  EXPECT_FALSE(open.value().direct);
  EXPECT_FALSE(open.value().exact_offset_grid);
}

TEST(PathPlanner, StartVelocitySetsTheStartDirectionWithUnitSpeed) {
  const JointVector start{{1.0, 1.57}}, goal{{0.2, 1.57}};
  const JointVector v0{{0.8, 2.0}};  // moving up and rotating while the goal is below
  const auto result = planner().plan(start, goal, HeldPieces{}, v0);
  ASSERT_TRUE(result.ok()) << result.error().message;
  const PathPoint p = result.value().path->at(0.0);
  const JointVector& metric = model().planner.metric;
  const double speed = std::sqrt(metric[0] * v0[0] * v0[0] + metric[1] * v0[1] * v0[1]);
  EXPECT_NEAR((p.dq_ds - v0 / speed).norm(), 0.0, 1e-12);
  EXPECT_TRUE(result.value().lead_in);
  const DenseCheck check = denseCheck(*result.value().path, planner().world(HeldPieces{}));
  EXPECT_GE(check.min_distance, model().clearance_m);
  EXPECT_TRUE(check.within_limits);
}

TEST(PathPlanner, StartVelocityIntoALimitShortensTheLeadIn) {
  // Moving down fast near the bottom of the rail: the lead-in is halved until it fits.
  const JointVector start{{0.2, 1.57}}, goal{{1.2, 1.57}}, v0{{-5.0, 0.0}};
  const auto result = planner().plan(start, goal, HeldPieces{}, v0);
  ASSERT_TRUE(result.ok()) << result.error().message;
  EXPECT_TRUE(result.value().lead_in);
  const JointVector lead = result.value().waypoints[1];
  EXPECT_LT(lead[0], start[0]);
  EXPECT_GE(lead[0], 0.0);
  EXPECT_NEAR(lead[1], start[1], 1e-12);
  const DenseCheck check = denseCheck(*result.value().path, planner().world(HeldPieces{}));
  EXPECT_GE(check.min_distance, model().clearance_m);
  EXPECT_TRUE(check.within_limits);
}

TEST(PathPlanner, MovingStartWithTheSameGoalGoesOutAndBack) {
  const JointVector q{{1.0, 1.57}}, v0{{0.5, 1.0}};
  const auto result = planner().plan(q, q, HeldPieces{}, v0);
  ASSERT_TRUE(result.ok()) << result.error().message;
  const GeometricPath& path = *result.value().path;
  EXPECT_GT(path.length(), 0.0);
  EXPECT_NEAR((path.at(path.length()).q - q).norm(), 0.0, 1e-12);
  EXPECT_GT(path.at(0.0).dq_ds.dot(v0), 0.0);
}

TEST(PathPlanner, RandomRequestsGiveValidPathsOrTypedErrors) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> t(0.0, 2.0), th(0.0, 6.1), v(-3.0, 3.0);
  std::uniform_int_distribution<int> set(0, 3);
  int ok = 0, refused = 0, no_path = 0;
  while (ok + refused < 40) {
    const HeldPieces pieces = HeldPieces::fromIndex(set(rng));
    const JointVector start{{t(rng), th(rng)}}, goal{{t(rng), th(rng)}};
    const CollisionWorld& world = planner().world(pieces);
    if (world.distance(start).value < model().clearance_m || world.distance(goal).value < model().clearance_m) continue;
    const JointVector v0 = (ok + refused) % 2 == 0 ? JointVector::Zero(2) : JointVector{{v(rng), 3.0 * v(rng)}};
    const auto result = planner().plan(start, goal, pieces, v0);
    if (!result.ok()) {
      ++refused;
      no_path += result.status() == PlanStatus::kNoPath ? 1 : 0;
      EXPECT_TRUE(result.status() == PlanStatus::kNoPath || result.status() == PlanStatus::kClearanceNotMet)
          << toString(result.status()) << ": " << result.error().message;
      EXPECT_FALSE(result.error().message.empty());
      if (result.status() == PlanStatus::kNoPath && v0.isZero()) {
        EXPECT_TRUE(separated(pieces, start, goal)) << start.transpose() << " -> " << goal.transpose();
      }
      continue;
    }
    ++ok;
    const GeometricPath& path = *result.value().path;
    EXPECT_EQ(path.at(0.0).q, start);
    EXPECT_NEAR((path.at(path.length()).q - goal).norm(), 0.0, 1e-12);
    if (!v0.isZero()) {
      const JointVector& m = model().planner.metric;
      const double speed = std::sqrt(m[0] * v0[0] * v0[0] + m[1] * v0[1] * v0[1]);
      EXPECT_NEAR((path.at(0.0).dq_ds - v0 / speed).norm(), 0.0, 1e-9);
    }
    const DenseCheck check = denseCheck(path, world);
    EXPECT_GE(check.min_distance, model().clearance_m) << start.transpose() << " -> " << goal.transpose();
    EXPECT_TRUE(check.within_limits) << start.transpose() << " -> " << goal.transpose();
  }
  std::printf("%d planned, %d refused (%d no path)\n", ok, refused, no_path);
  EXPECT_GT(ok, 20);
}

TEST(PathPlanner, HeldPiecesShapeThePath) {
  // A held piece makes the robot bigger: its grid blocks more, and a path planned for the bare
  // arm can come closer than the clearance once the piece is held, while the piece's path does not.
  EXPECT_GT(planner().grid(test::referencePieces("algae")).blockedCount(), planner().grid(HeldPieces{}).blockedCount());
  const HeldPieces coral = test::referencePieces("coral");
  int bare_path_too_close = 0;
  for (const test::PublicMove& move : test::publicMoves()) {
    if (move.pieces != coral || bare_path_too_close > 0) continue;
    const auto with_coral = planner().plan(move.from, move.to, coral);
    const auto bare = planner().plan(move.from, move.to, HeldPieces{});
    if (!with_coral.ok() || !bare.ok()) continue;
    EXPECT_GE(denseCheck(*with_coral.value().path, planner().world(coral)).min_distance, model().clearance_m);
    if (denseCheck(*bare.value().path, planner().world(coral)).min_distance < model().clearance_m)
      ++bare_path_too_close;
  }
  EXPECT_GT(bare_path_too_close, 0);
}

}  // namespace
}  // namespace cyber::planner

// The shipped robots (config/*.toml): every ordered pair of their named poses, per held set,
// is planned within its stored ceiling (or refused where the table says so), and every plan keeps
// the clearance and the drive limits at 1 ms and is within 1.02 of the fastest ride along its path;
// scene offsets move the field elements and the plan with them (docs/algorithm.md section 2,
// "Scene offsets").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "cyber/config/load_config.hpp"
#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/motion_planner.hpp"
#include "cyber/planner/trajectory.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"
#include "shipped_move_durations.hpp"
#include "shipped_robots.hpp"

namespace cyber::planner {
namespace {

using test::expectSound;
using test::namedPose;
using test::shippedRobot;
using test::ShippedRobot;

// Named moves whose columns do not agree at 1 ms, checked at the spacing cyber-plan writes them at
// and the referee passes (docs/moving-starts.md, "The CSV's spacing"). The elevator-pivot-wrist's
// 50 ms PROCESSOR -> ALGAE_GROUND: its velocity column is 2.06 % of the peak speed off at 1 ms.
// An entry whose move comes to agree at 1 ms fails, so that it is taken out.
struct FinerColumns {
  const char* robot;
  const char* pieces;
  const char* from;
  const char* to;
  double step_s;
};
constexpr FinerColumns kFinerColumns[] = {
    {"reefscape-2025-elevator-pivot-wrist", "none", "PROCESSOR", "ALGAE_GROUND", 0.0005},
};

double columnsStepFor(const test::ShippedMoveCeiling& move) {
  for (const FinerColumns& finer : kFinerColumns) {
    if (std::string(finer.robot) == move.robot && std::string(finer.pieces) == move.pieces &&
        std::string(finer.from) == move.from && std::string(finer.to) == move.to)
      return finer.step_s;
  }
  return 0.001;
}

TEST(ShippedRobots, EveryNamedMoveIsPlannedWithinItsCeilingOrRefusedAsStored) {
  int planned = 0, refused = 0;
  std::map<std::string, double> worst_ratio;
  for (const test::ShippedMoveCeiling& move : test::kShippedMoveCeilings) {
    const ShippedRobot& robot = shippedRobot(move.robot);
    const RobotModel& model = robot.config.robot;
    const std::string label = std::string(move.robot) + " " + move.pieces + ":" + move.from + "->" + move.to;
    const auto pieces = model.piecesNamed(move.pieces);
    ASSERT_TRUE(pieces.ok()) << pieces.error().message;
    PlanRequest request;
    request.start = namedPose(robot.config, move.pieces, move.from);
    request.goal = namedPose(robot.config, move.pieces, move.to);
    request.pieces = pieces.value();
    const auto plan = robot.planner.plan(request);
    if (move.ceiling_s == test::kRefused) {
      EXPECT_FALSE(plan.ok()) << label << " is now planned: update the table";
      ++refused;
      continue;
    }
    ASSERT_TRUE(plan.ok()) << label << ": " << plan.error().message;
    EXPECT_LE(plan.value().trajectory->duration_s(), move.ceiling_s) << label;
    const double columns_step_s = columnsStepFor(move);
    expectSound(model, *plan.value().trajectory, pieces.value(), 0.0, label, columns_step_s);
    if (columns_step_s < 0.001) {
      const ColumnConsistency at_1_ms = columnConsistency(*plan.value().trajectory, 0.001);
      EXPECT_FALSE(at_1_ms.position_error <= 0.01 && at_1_ms.velocity_error <= 0.02)
          << label << " now agrees at 1 ms: take it out of kFinerColumns";
    }
    worst_ratio[move.robot] =
        std::max(worst_ratio[move.robot], test::expectNearTheFastestRide(*plan.value().trajectory, label));
    ++planned;
  }
  EXPECT_EQ(planned + refused, static_cast<int>(std::size(test::kShippedMoveCeilings)));
  EXPECT_GT(planned, 100);
  for (const auto& [robot, ratio] : worst_ratio)
    RecordProperty(std::string(robot) + "_worst_ratio_to_ride", std::to_string(ratio));
}

// The pivot-telescope's STOW and REACH_UP lie on the telescope's limits (0 and 0.9 m). A straight
// move to or from them was refused: its spline, evaluated at the end knot, came out a few ulp
// outside the limit. These moves are planned and stay inside the limits at every 1 ms sample.
TEST(ShippedRobots, MovesBetweenPosesOnTheTelescopesLimitsArePlannedInsideTheLimits) {
  const ShippedRobot& robot = shippedRobot("pivot-telescope");
  const RobotModel& model = robot.config.robot;
  const std::pair<const char*, const char*> moves[] = {
      {"STOW", "REACH_UP"}, {"SCORE_HIGH", "STOW"}, {"HUMAN_LOAD", "STOW"}, {"REACH_UP", "STOW"}};
  for (const char* set : {"none", "ball"}) {
    for (const auto& [from, to] : moves) {
      const std::string label = std::string(set) + ":" + from + "->" + to;
      PlanRequest request;
      request.start = namedPose(robot.config, set, from);
      request.goal = namedPose(robot.config, set, to);
      request.pieces = model.piecesNamed(set).value();
      ASSERT_FALSE(model.withinLimits(request.start, -1e-3) && model.withinLimits(request.goal, -1e-3)) << label;
      const auto plan = robot.planner.plan(request);
      ASSERT_TRUE(plan.ok()) << label << ": " << plan.error().message;
      const Trajectory& trajectory = *plan.value().trajectory;
      EXPECT_EQ(trajectory.sampleMotion(0.0).q, request.start) << label;
      EXPECT_NEAR((trajectory.sampleMotion(trajectory.duration_s()).q - request.goal).norm(), 0.0, 1e-9) << label;
      expectSound(model, trajectory, request.pieces, 0.0, label);
    }
  }
}

TEST(ShippedRobots, TheDoubleJointedArmIsDrivenByItsCoupledDynamics) {
  const RobotModel& model = shippedRobot("chargedup-2023-double-jointed").config.robot;
  EXPECT_EQ(model.drive_kind, DriveKind::kRigidBody);
  // The shoulder's gravity load depends on the elbow: the same shoulder angle, two elbow angles.
  const DriveModel drives = model.driveModel({});
  const JointVector rest = JointVector::Zero(2);
  EXPECT_GT(std::abs(drives.volts(JointVector{{0.5, 1.0}}, rest, rest)[0] -
                     drives.volts(JointVector{{0.5, 3.0}}, rest, rest)[0]),
            0.1);
  // A held cone adds its weight.
  const HeldPieces cone = model.piecesNamed("cone").value();
  EXPECT_GT(std::abs(model.driveModel(cone).volts(JointVector{{0.5, 1.0}}, rest, rest)[1]),
            std::abs(drives.volts(JointVector{{0.5, 1.0}}, rest, rest)[1]));
}

// A seeded random moving start of the double-jointed arm (the state 0.199 s into a planned move):
// a 17 ms stop, then a 0.2 s move. Every gentler stop still disagreed at 1 ms (the trapezoid's
// errors add up over the whole move), and so did leaving along the velocity; the plan streamed
// was 0.2338 s with its acceleration columns 2.5 % of the peak speed off. The onward plan from
// the fastest stop, slowed until the joined columns agree, is faster as well
// (docs/moving-starts.md, "Consistent columns").
TEST(ShippedRobots, AShortMoveAfterAShortStopIsSlowedUntilTheJoinedColumnsAgree) {
  const ShippedRobot& robot = shippedRobot("chargedup-2023-double-jointed");
  PlanRequest request;
  request.start = JointVector{{1.49215116, 3.97783964}};
  request.goal = JointVector{{1.9864, 3.7218}};
  request.start_velocity = JointVector{{-2.61471287, 0.391380071}};
  const auto plan = robot.planner.plan(request);
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  EXPECT_TRUE(plan.value().method.has(PlanMethod::kSlowedAfterStop)) << plan.value().method.name();
  const ColumnConsistency c = columnConsistency(*plan.value().trajectory, 0.001);
  EXPECT_LE(c.position_error, 0.01);
  EXPECT_LE(c.velocity_error, 0.02);
  EXPECT_LT(plan.value().trajectory->duration_s(), 0.2338);
}

// A scene offset that moves the reef into the path planned at offset 0 gives another plan, which
// keeps the clearance at that offset. Of the public moves, two are such cases (their ends stay clear
// and the reef, moved 0.1-0.3 m away, crosses the plan of offset 0).
TEST(ShippedRobots, AnOffsetThatMovesTheReefIntoThePlanYieldsAnotherPlanThatKeepsTheClearance) {
  const RobotModel& model = test::referenceModel();
  const auto planner = MotionPlanner::create(model);
  ASSERT_TRUE(planner.ok());
  int moved_into = 0;
  for (const test::PublicMove& move : test::publicMoves()) {
    PlanRequest request;
    request.start = move.from;
    request.goal = move.to;
    request.pieces = move.pieces;
    const auto at_zero = planner.value().plan(request);
    if (!at_zero.ok()) continue;
    for (const double offset : {0.1, 0.2, 0.3}) {
      const CollisionWorld world(model, model.scenes.front(), move.pieces, offset);
      if (world.distance(move.from).value < model.clearance_m || world.distance(move.to).value < model.clearance_m) {
        continue;  // the offset moves the reef onto an end of the move
      }
      double closest = 1e9;
      for (double t = 0.0; t <= at_zero.value().trajectory->duration_s(); t += 0.001) {
        closest = std::min(closest, world.distance(at_zero.value().trajectory->sampleMotion(t).q).value);
      }
      if (closest >= model.clearance_m) continue;
      request.scene_offset_m = offset;
      const std::string label = move.label + " at offset " + std::to_string(offset);
      const auto shifted = planner.value().plan(request);
      ASSERT_TRUE(shifted.ok()) << label << ": " << shifted.error().message;
      expectSound(model, *shifted.value().trajectory, move.pieces, offset, label);
      ++moved_into;
      break;
    }
  }
  EXPECT_GE(moved_into, 2);
  PlanRequest outside;
  outside.start = JointVector{{0.20, 1.57}};
  outside.goal = JointVector{{1.22, 5.69}};
  outside.scene_offset_m = 0.31;
  EXPECT_EQ(planner.value().plan(outside).status(), PlanStatus::kInvalidInput);
}

TEST(ShippedRobots, EachBandOfOffsetsIsAtMostItsWidthAndTheyCoverTheRange) {
  const RobotModel& model = test::referenceModel();
  const auto planner = MotionPlanner::create(model);
  ASSERT_TRUE(planner.ok());
  const std::vector<JointRange> bands = planner.value().offsetBands(0);
  ASSERT_GE(bands.size(), 2u);
  EXPECT_EQ(bands.front().min, 0.0);
  EXPECT_EQ(bands.front().max, 0.0);
  const double width = model.planner.search.offset_band_clearances * model.clearance_m;
  EXPECT_DOUBLE_EQ(bands[1].min, model.scenes.front().offset_range_m.min);
  EXPECT_DOUBLE_EQ(bands.back().max, model.scenes.front().offset_range_m.max);
  for (size_t k = 1; k < bands.size(); ++k) {
    EXPECT_LE(bands[k].max - bands[k].min, width + 1e-12);
    if (k > 1) {
      EXPECT_DOUBLE_EQ(bands[k].min, bands[k - 1].max);
    }
  }
  EXPECT_EQ(planner.value().offsetBands(1).size(), 1u);  // the open scene has no field elements
}

// A planner built for one scene and offset only (cyber-plan's) plans that move as the full one does
// and refuses what it has no grids for.
TEST(ShippedRobots, APlannerOfOneSceneAndOffsetPlansItsMovesAsTheFullOneDoes) {
  const RobotModel& model = test::referenceModel();
  const auto full = MotionPlanner::create(model);
  ASSERT_TRUE(full.ok());
  PlanRequest request;
  request.start = JointVector{{0.20, 1.57}};
  request.goal = JointVector{{1.22, 5.69}};
  for (const double offset : {0.0, 0.2}) {
    request.scene_offset_m = offset;
    const auto selected = MotionPlanner::create(model, {0, offset});
    ASSERT_TRUE(selected.ok());
    const auto a = full.value().plan(request);
    const auto b = selected.value().plan(request);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a.value().trajectory->duration_s(), b.value().trajectory->duration_s()) << offset;
    PlanRequest elsewhere = request;
    elsewhere.scene_offset_m = offset == 0.0 ? 0.2 : 0.0;
    EXPECT_EQ(selected.value().plan(elsewhere).status(), PlanStatus::kInvalidInput) << offset;
    elsewhere = request;
    elsewhere.scene = 1;
    EXPECT_EQ(selected.value().plan(elsewhere).status(), PlanStatus::kInvalidInput) << offset;
  }
}

}  // namespace
}  // namespace cyber::planner

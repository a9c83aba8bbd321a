// The planner's front door (motion_planner.hpp): the models create() refuses, the requests plan()
// and stop() refuse before any search (unknown scene, offset outside the scene's range or the
// grids built, velocity not finite), what the path stage refuses passed on, a plan from rest that
// starts and ends where asked, the grids a GridSelection builds, and stop() as the fastest stop in
// the request's world.

#include "cyber/planner/motion_planner.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "motion/fastest_stop.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"

namespace cyber::planner {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The reef scene as drawn (offset 0) alone: the grids most requests here need, built once.
const MotionPlanner& reefPlanner() {
  static const MotionPlanner planner = [] {
    auto created = MotionPlanner::create(test::referenceModel(), GridSelection{0, 0.0});
    EXPECT_TRUE(created.ok()) << created.error().message;
    return std::move(created).value();
  }();
  return planner;
}

void expectRefused(const Result<Plan>& plan, PlanStatus status, const std::string& message) {
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.status(), status) << plan.error().message;
  EXPECT_EQ(plan.error().message, message);
}

TEST(MotionPlanner, CreateRefusesAModelItCannotPlanFor) {
  RobotModel no_scene = test::referenceModel();
  no_scene.scenes.clear();
  auto created = MotionPlanner::create(no_scene);
  ASSERT_FALSE(created.ok());
  EXPECT_EQ(created.status(), PlanStatus::kInvalidInput);
  EXPECT_EQ(created.error().message, "the robot has no scene");

  RobotModel no_polygon = test::referenceModel();
  ASSERT_FALSE(no_polygon.links.empty());
  for (LinkGeometry& link : no_polygon.links) link.polygons.clear();
  created = MotionPlanner::create(no_polygon);
  ASSERT_FALSE(created.ok());
  EXPECT_EQ(created.status(), PlanStatus::kInvalidInput);
  EXPECT_EQ(created.error().message, "the robot has no link polygons");

  RobotModel crowded = test::referenceModel();
  while (static_cast<int>(crowded.pieces.size()) <= HeldPieces::kMaxPieces) {
    crowded.pieces.push_back(GamePiece{"piece " + std::to_string(crowded.pieces.size()), 1, {}});
  }
  created = MotionPlanner::create(crowded);
  ASSERT_FALSE(created.ok());
  EXPECT_EQ(created.status(), PlanStatus::kInvalidInput);
  EXPECT_EQ(created.error().message, "at most 4 game pieces");
}

TEST(MotionPlanner, PlanRefusesAnUnknownScene) {
  const int scenes = static_cast<int>(test::referenceModel().scenes.size());
  for (const int scene : {-1, scenes, scenes + 7}) {
    PlanRequest request;
    request.scene = scene;
    expectRefused(reefPlanner().plan(request), PlanStatus::kInvalidInput,
                  "unknown scene index " + std::to_string(scene));
    request.start_velocity = JointVector{{0.5, 0.0}};
    expectRefused(reefPlanner().stop(request), PlanStatus::kInvalidInput,
                  "unknown scene index " + std::to_string(scene));
  }
}

TEST(MotionPlanner, PlanRefusesAnOffsetOutsideTheScenesRange) {
  const JointRange range = test::referenceModel().scenes.front().offset_range_m;
  ASSERT_EQ(range.min, 0.0);
  ASSERT_EQ(range.max, 0.3);
  const auto stow = test::publicMove("none:STOW->L4");
  for (const double offset : {-0.01, 0.3001, kNaN, kInf, -kInf}) {
    PlanRequest request;
    request.start = stow.from;
    request.goal = stow.to;
    request.scene_offset_m = offset;
    const auto plan = reefPlanner().plan(request);
    ASSERT_FALSE(plan.ok()) << offset;
    EXPECT_EQ(plan.status(), PlanStatus::kInvalidInput) << offset;
    EXPECT_NE(plan.error().message.find("is outside scene reef's range [0.0000, 0.3000] m"), std::string::npos)
        << plan.error().message;
  }
  // A scene that does not move has the range {0, 0}.
  PlanRequest open;
  open.scene = test::referenceModel().sceneIndex("open");
  open.scene_offset_m = 0.1;
  expectRefused(reefPlanner().plan(open), PlanStatus::kInvalidInput,
                "scene offset 0.1000 m is outside scene open's range [0.0000, 0.0000] m");
}

TEST(MotionPlanner, PlanRefusesAStartVelocityThatIsNotFinite) {
  const auto move = test::publicMove("none:STOW->L4");
  for (const JointVector& velocity : {JointVector{{kNaN, 0.0}}, JointVector{{0.0, kInf}}, JointVector{{-kInf, kNaN}}}) {
    PlanRequest request;
    request.start = move.from;
    request.goal = move.to;
    request.start_velocity = velocity;
    expectRefused(reefPlanner().plan(request), PlanStatus::kInvalidInput, "start velocity is not finite");
  }
}

// What the path stage refuses, plan() returns as it is.
TEST(MotionPlanner, PlanPassesOnThePathStagesRefusals) {
  const RobotModel& model = test::referenceModel();
  const auto move = test::publicMove("none:STOW->L4");
  PlanRequest request;
  request.start = JointVector{{kNaN, move.from.y()}};
  request.goal = move.to;
  expectRefused(reefPlanner().plan(request), PlanStatus::kInvalidInput, "start pose is not a finite number");
  request.start = move.from;
  request.goal = JointVector{{model.range(0).max + 0.1, move.to.y()}};
  const auto out = reefPlanner().plan(request);
  ASSERT_FALSE(out.ok());
  EXPECT_EQ(out.status(), PlanStatus::kGoalOutOfRange);
}

// From rest to rest: it starts and ends where asked, keeps the clearance it reports, stays within
// the drives' limits and its columns agree at the CSV's step; a copy of the planner plans the
// same.
TEST(MotionPlanner, APlanFromRestStartsAndEndsWhereAsked) {
  const RobotModel& model = test::referenceModel();
  const auto move = test::publicMove("coral:STOW->L3");
  PlanRequest request;
  request.start = move.from;
  request.goal = move.to;
  request.pieces = move.pieces;
  const auto plan = reefPlanner().plan(request);
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  const Trajectory& t = *plan.value().trajectory;
  EXPECT_LT((t.sample(0.0).q - move.from).norm(), 1e-9);
  EXPECT_LT((t.sample(t.duration_s()).q - move.to).norm(), 1e-6);
  EXPECT_LT(t.sample(0.0).qdot.norm(), 1e-9);
  EXPECT_LT(t.sample(t.duration_s()).qdot.norm(), 1e-6);
  ASSERT_GE(plan.value().waypoints.size(), 2u);
  EXPECT_EQ(plan.value().waypoints.front(), move.from);
  EXPECT_EQ(plan.value().waypoints.back(), move.to);
  EXPECT_GE(plan.value().min_clearance_m, model.clearance_m);
  EXPECT_FALSE(plan.value().method.strategy.empty());
  EXPECT_TRUE(withinDriveLimits(t, model.planner.topp));
  const ColumnConsistency c = columnConsistency(t, model.planner.motion.consistency_step_s);
  EXPECT_LE(c.position_error, model.planner.motion.max_position_error);
  EXPECT_LE(c.velocity_error, model.planner.motion.max_velocity_error);
  const MotionPlanner copy = reefPlanner();
  const auto again = copy.plan(request);
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again.value().trajectory->duration_s(), t.duration_s());
  EXPECT_EQ(copy.model().name, model.name);
}

// A GridSelection builds the grids of one scene and offset: requests for any other are refused
// (they would need grids the planner does not have), the selected ones are planned.
TEST(MotionPlanner, APlannerOfSomeGridsRefusesTheOthers) {
  const auto move = test::publicMove("none:STOW->L4");
  PlanRequest request;
  request.start = move.from;
  request.goal = move.to;
  request.scene = test::referenceModel().sceneIndex("open");
  expectRefused(reefPlanner().plan(request), PlanStatus::kInvalidInput,
                "this planner was built without the grids of scene open at offset 0.0000 m");
  request.scene = 0;
  request.scene_offset_m = 0.1;
  expectRefused(reefPlanner().plan(request), PlanStatus::kInvalidInput,
                "this planner was built without the grids of scene reef at offset 0.1000 m");
  ASSERT_EQ(reefPlanner().offsetBands(0).size(), 1u);
  EXPECT_EQ(reefPlanner().offsetBands(0)[0].min, 0.0);
  EXPECT_EQ(reefPlanner().offsetBands(0)[0].max, 0.0);

  // The band of 0.1 alone: one band around it, no wider than the settings' share of clearances.
  const RobotModel& model = test::referenceModel();
  const auto band_only = MotionPlanner::create(model, GridSelection{0, 0.1});
  ASSERT_TRUE(band_only.ok());
  const std::vector<JointRange> bands = band_only.value().offsetBands(0);
  ASSERT_EQ(bands.size(), 1u);
  EXPECT_TRUE(bands[0].contains(0.1));
  EXPECT_LE(bands[0].max - bands[0].min,
            model.planner.search.offset_band_clearances * model.clearance_m * (1.0 + 1e-9));
  const auto planned = band_only.value().plan(request);
  ASSERT_TRUE(planned.ok()) << planned.error().message;
  EXPECT_LT((planned.value().trajectory->sample(planned.value().trajectory->duration_s()).q - move.to).norm(), 1e-6);
  for (const double other : {0.0, bands[0].max + 0.01, bands[0].min - 0.01}) {
    if (!model.scenes[0].offset_range_m.contains(other) || bands[0].contains(other)) continue;
    request.scene_offset_m = other;
    const auto refused = band_only.value().plan(request);
    ASSERT_FALSE(refused.ok()) << other;
    EXPECT_EQ(refused.status(), PlanStatus::kInvalidInput) << other;
    EXPECT_NE(refused.error().message.find("this planner was built without the grids"), std::string::npos)
        << refused.error().message;
  }
}

// stop() is the fastest stop along the start velocity in the request's world: the scene as drawn,
// or its field elements shifted by the offset; the goal plays no part.
TEST(MotionPlanner, StopIsTheFastestStopInTheRequestsWorld) {
  const RobotModel& model = test::referenceModel();
  PlanRequest request;
  request.start = JointVector{{1.0, 3.0}};
  request.start_velocity = JointVector{{0.8, -3.0}};
  request.goal = JointVector{{0.2, 0.2}};
  for (const double offset : {0.0, 0.2}) {
    request.scene_offset_m = offset;
    const auto stop = reefPlanner().stop(request);
    ASSERT_TRUE(stop.ok()) << stop.error().message;
    ToppSolver solver(model.planner.topp);
    const CollisionWorld world(model, model.scenes.front(), HeldPieces{}, offset);
    const auto direct = fastestStop(model, world, request.start, request.start_velocity, solver);
    ASSERT_TRUE(direct.ok()) << direct.error().message;
    EXPECT_EQ(stop.value().trajectory->duration_s(), direct.value().duration_s()) << offset;
    EXPECT_EQ(stop.value().trajectory->sGrid(), direct.value().sGrid()) << offset;
    EXPECT_LT(stop.value().trajectory->sample(stop.value().trajectory->duration_s()).qdot.norm(), 1e-9);
  }
  request.scene_offset_m = 0.0;
  request.goal = JointVector{{1.5, 5.0}};
  const auto same = reefPlanner().stop(request);
  ASSERT_TRUE(same.ok());
  EXPECT_EQ(same.value().trajectory->sGrid(), reefPlanner().stop(request).value().trajectory->sGrid());
}

// A stop is refused at an offset a plan is refused at (a NaN offset once made every distance NaN,
// which no clearance check refuses), and is made for a scene whose grids were left out: it needs
// none.
TEST(MotionPlanner, StopChecksTheOffsetAndNeedsNoGrid) {
  PlanRequest request;
  request.start = JointVector{{1.0, 3.0}};
  request.start_velocity = JointVector{{0.8, -3.0}};
  for (const double offset : {-0.01, 0.3001, kNaN, kInf}) {
    request.scene_offset_m = offset;
    const auto refused = reefPlanner().stop(request);
    ASSERT_FALSE(refused.ok()) << offset;
    EXPECT_EQ(refused.status(), PlanStatus::kInvalidInput) << offset;
    EXPECT_NE(refused.error().message.find("is outside scene reef's range"), std::string::npos)
        << refused.error().message;
  }
  const RobotModel& model = test::referenceModel();
  auto other_scene_only = MotionPlanner::create(model, GridSelection{model.sceneIndex("open"), 0.0});
  ASSERT_TRUE(other_scene_only.ok());
  request.scene_offset_m = 0.0;
  const auto stop = other_scene_only.value().stop(request);
  ASSERT_TRUE(stop.ok()) << stop.error().message;
  EXPECT_EQ(stop.value().trajectory->duration_s(), reefPlanner().stop(request).value().trajectory->duration_s());
  EXPECT_TRUE(other_scene_only.value().offsetBands(-1).empty());
  EXPECT_TRUE(other_scene_only.value().offsetBands(99).empty());
}

TEST(MotionPlanner, StopRefusesAVelocityThatIsZeroOrNotFinite) {
  for (const JointVector& velocity :
       {JointVector::Zero(2).eval(), JointVector{{kNaN, 1.0}}, JointVector{{0.0, kInf}}}) {
    PlanRequest request;
    request.start = JointVector{{1.0, 3.0}};
    request.start_velocity = velocity;
    expectRefused(reefPlanner().stop(request), PlanStatus::kInvalidInput, "no velocity to stop from");
  }
}

}  // namespace
}  // namespace cyber::planner

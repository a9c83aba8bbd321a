// The robot description's look-ups (robot_model.hpp): scenes, pieces and joints by name, held sets
// by name and back for every subset, the names it refuses and what the refusal says, and the drive
// model of a held set under either kind of drive.

#include "cyber/planner/robot_model.hpp"

#include <array>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "reference_model.hpp"

namespace cyber::planner {
namespace {

// The reference robot with a third piece, declared last, so that sets of more than two have an
// order to keep.
RobotModel threePieces() {
  RobotModel model = test::referenceModel();
  model.pieces.push_back(GamePiece{"cube", test::kArm, {}});
  return model;
}

TEST(RobotModel, EveryNameFindsItsIndexAndNoOtherNameDoes) {
  const RobotModel& model = test::referenceModel();
  ASSERT_GE(model.scenes.size(), 2u);
  for (size_t i = 0; i < model.scenes.size(); ++i)
    EXPECT_EQ(model.sceneIndex(model.scenes[i].name), static_cast<int>(i));
  for (size_t i = 0; i < model.pieces.size(); ++i)
    EXPECT_EQ(model.pieceIndex(model.pieces[i].name), static_cast<int>(i));
  EXPECT_EQ(model.jointIndex("elevator"), test::kElevator);
  EXPECT_EQ(model.jointIndex("arm"), test::kArm);
  for (const std::string unknown : {"", "Reef", "reef ", "coral+algae", "none", "wrist"}) {
    EXPECT_EQ(model.sceneIndex(unknown), -1) << unknown;
    EXPECT_EQ(model.pieceIndex(unknown), -1) << unknown;
    EXPECT_EQ(model.jointIndex(unknown), -1) << unknown;
  }
}

TEST(RobotModel, EveryHeldSetIsNamedAndReadBack) {
  const RobotModel model = threePieces();
  ASSERT_EQ(model.pieceSetCount(), 8);
  EXPECT_EQ(model.allPieces(), HeldPieces{0b111});
  for (int set = 0; set < model.pieceSetCount(); ++set) {
    const HeldPieces held = HeldPieces::fromIndex(set);
    const std::string name = model.pieceSetName(held);
    const auto read = model.piecesNamed(name);
    ASSERT_TRUE(read.ok()) << name << ": " << read.error().message;
    EXPECT_EQ(read.value(), held) << name;
  }
  // Declaration order, joined by '+', whatever order the bits were set in.
  const std::string& first = model.pieces[0].name;
  const std::string& second = model.pieces[1].name;
  EXPECT_EQ(model.pieceSetName(HeldPieces{}), "none");
  EXPECT_EQ(model.pieceSetName(HeldPieces{}.with(2).with(0)), first + "+cube");
  EXPECT_EQ(model.pieceSetName(HeldPieces{}.with(1)), second);
  EXPECT_EQ(model.pieceSetName(model.allPieces()), first + "+" + second + "+cube");
}

TEST(RobotModel, HeldSetsAreReadWithEitherSeparatorInAnyOrder) {
  const RobotModel model = threePieces();
  const HeldPieces coral_cube = HeldPieces{}.with(model.pieceIndex("coral")).with(model.pieceIndex("cube"));
  for (const char* names : {"coral+cube", "cube+coral", "coral,cube", "cube,coral", "coral+cube,coral"}) {
    const auto held = model.piecesNamed(names);
    ASSERT_TRUE(held.ok()) << names;
    EXPECT_EQ(held.value(), coral_cube) << names;
  }
  EXPECT_EQ(model.piecesNamed("").value(), HeldPieces{});
  EXPECT_EQ(model.piecesNamed("none").value(), HeldPieces{});
}

// A name that is not one of the pieces is refused, with the name and the robot's own pieces (an
// empty name is what a separator at either end leaves).
TEST(RobotModel, AnUnknownPieceIsRefusedWithTheNamesThereAre) {
  const RobotModel& model = test::referenceModel();
  ASSERT_EQ(model.pieces.size(), 2u);
  const struct {
    const char* names;
    const char* unknown;
  } kRefused[] = {
      {"cone", "cone"},     {"coral+cone", "cone"},         {"Coral", "Coral"},    {"coral+", ""}, {"+coral", ""},
      {"coral++algae", ""}, {"coral algae", "coral algae"}, {"none+coral", "none"}};
  // The robot's pieces in declaration order.
  const std::string known = model.pieces[0].name + ", " + model.pieces[1].name;
  for (const auto& r : kRefused) {
    const auto refused = model.piecesNamed(r.names);
    ASSERT_FALSE(refused.ok()) << r.names;
    EXPECT_EQ(refused.status(), PlanStatus::kInvalidInput) << r.names;
    EXPECT_EQ(refused.error().message,
              "unknown game piece \"" + std::string(r.unknown) + "\" (this robot's: " + known + ")")
        << r.names;
  }
  RobotModel bare = model;
  bare.pieces.clear();
  const auto refused = bare.piecesNamed("coral");
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().message, "unknown game piece \"coral\" (this robot's: none)");
  EXPECT_EQ(bare.pieceSetCount(), 1);
  EXPECT_EQ(bare.allPieces(), HeldPieces{});
}

TEST(RobotModel, WithinLimitsIsBothJointsRangesWithTheTolerance) {
  const RobotModel& model = test::referenceModel();
  const JointRange e = model.range(test::kElevator), a = model.range(test::kArm);
  EXPECT_TRUE(model.withinLimits(JointVector{{e.min, a.max}}));
  EXPECT_TRUE(model.withinLimits(JointVector{{e.max, a.min}}));
  EXPECT_FALSE(model.withinLimits(JointVector{{e.max + 1e-9, a.min}}));
  EXPECT_FALSE(model.withinLimits(JointVector{{e.min, a.min - 1e-9}}));
  EXPECT_TRUE(model.withinLimits(JointVector{{e.max + 1e-9, a.min - 1e-9}}, 2e-9));
  EXPECT_FALSE(model.withinLimits(JointVector{{e.max + 3e-9, a.min}}, 2e-9));
}

// Under the feedforward kind the held pieces change nothing (their mass is in the gains); under the
// rigid-body kind each held piece's mass joins its link's body (parallel-axis theorem), a piece
// without mass data adds none, and the pieces not held add nothing.
TEST(RobotModel, DriveModelOfAHeldSetAddsItsPiecesToTheirLinks) {
  RobotModel model = threePieces();
  const JointVector q{{0.8, 2.0}}, qdot{{0.3, -1.0}}, qddot{{2.0, 5.0}};
  const JointVector bare = DriveModel(model.joints, model.drives).volts(q, qdot, qddot);
  EXPECT_EQ(model.driveModel(model.allPieces()).kind(), DriveKind::kFeedforward);
  EXPECT_EQ(model.driveModel(model.allPieces()).volts(q, qdot, qddot), bare);

  model.drive_kind = DriveKind::kRigidBody;
  model.bodies = {LinkInertia{6.0, Point2(0.0, 0.1), 0.2}, LinkInertia{2.5, Point2(0.3, 0.0), 0.05}};
  model.piece_inertias = {LinkInertia{0.7, Point2(0.3, 0.0), 0.01}, LinkInertia{1.4, Point2(0.42, 0.0), 0.02}};
  // (the third piece, cube, has no mass data)
  for (int set = 0; set < model.pieceSetCount(); ++set) {
    const HeldPieces held = HeldPieces::fromIndex(set);
    PerJoint<LinkInertia> bodies = model.bodies;
    if (held.holds(0)) bodies[test::kArm] = combine(bodies[test::kArm], model.piece_inertias[0]);
    if (held.holds(1)) bodies[test::kArm] = combine(bodies[test::kArm], model.piece_inertias[1]);
    const DriveModel expected(model.drives, ChainDynamics(model.joints, bodies));
    const DriveModel drives = model.driveModel(held);
    EXPECT_EQ(drives.kind(), DriveKind::kRigidBody);
    const JointVector volts = drives.volts(q, qdot, qddot);
    EXPECT_LT((volts - expected.volts(q, qdot, qddot)).norm(), 1e-12) << model.pieceSetName(held);
  }
  const JointVector empty = model.driveModel(HeldPieces{}).volts(q, qdot, qddot);
  EXPECT_GT(std::abs(model.driveModel(HeldPieces{}.with(1)).volts(q, qdot, qddot)[test::kArm] - empty[test::kArm]),
            0.01);
  EXPECT_EQ(model.driveModel(HeldPieces{}.with(2)).volts(q, qdot, qddot), empty);
}

}  // namespace
}  // namespace cyber::planner

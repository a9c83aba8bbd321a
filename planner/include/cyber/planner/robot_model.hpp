#pragma once
// The robot description the planner works on: joints, polygons, scenes, drives and settings.
// Plain values; the TOML loader (config_loader) fills and validates them.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cyber/planner/chain.hpp"
#include "cyber/planner/planner_settings.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

/// Polygons attached to one link of the chain, in that link's frame (chain.hpp).
struct LinkGeometry {
  std::string name;
  int joint = 0;  ///< the link of this joint
  std::vector<ConvexPolygon> polygons;
};

/// A named game piece: polygons in its joint's link frame, present only while it is held.
struct GamePiece {
  std::string name;
  int joint = 0;
  std::vector<ConvexPolygon> polygons;
};

/// An obstacle of a scene: a name for messages and a polygon in the world frame.
struct NamedPolygon {
  std::string name;
  ConvexPolygon polygon;  ///< world frame
};

/// A named set of obstacles; the first scene of a model is its default. A goal may shift the
/// scene's field elements (`obstacles`) by an offset in x within offset_range_m (the robot's
/// distance to them; > 0 = the robot further away); `fixed` ones (keep-outs on the robot, the
/// floor) never move.
struct Scene {
  std::string name;
  std::vector<NamedPolygon> obstacles;
  std::vector<NamedPolygon> fixed;
  JointRange offset_range_m;  ///< {0, 0}: the scene does not move
};

/// The robot as the planner sees it: joints, link outlines, game pieces, scenes, drives, settings.
struct RobotModel {
  std::string name;
  JointChain joints;
  std::vector<LinkGeometry> links;  ///< at least one polygon in all
  std::vector<GamePiece> pieces;    ///< at most HeldPieces::kMaxPieces
  std::vector<Scene> scenes;        ///< scenes.front() is the default
  double clearance_m = 0.0;
  PerJoint<DriveParams> drives;  ///< one per joint
  DriveKind drive_kind = DriveKind::kFeedforward;
  /// Rigid-body drives: what moves with each link's frame (index = joint), and each piece's mass
  /// data by piece index (massless unless the description gives it).
  PerJoint<LinkInertia> bodies;
  std::vector<LinkInertia> piece_inertias;
  PlannerSettings planner;

  /// N, the number of joints of the chain (1 to kMaxJoints).
  [[nodiscard]] int jointCount() const { return joints.size(); }
  [[nodiscard]] const JointRange& range(int joint) const { return joints[joint].range; }
  [[nodiscard]] const DriveParams& drive(int joint) const { return drives[joint]; }
  /// Whether q has one value per joint, each within its range (widened by tolerance).
  [[nodiscard]] bool withinLimits(const JointVector& q, double tolerance = 0.0) const {
    if (q.size() != jointCount()) return false;
    for (int j = 0; j < jointCount(); ++j) {
      if (!range(j).contains(q[j], tolerance)) return false;
    }
    return true;
  }
  /// Index of a scene, a piece or a joint by name; -1 when there is none.
  [[nodiscard]] int sceneIndex(const std::string& name) const;
  [[nodiscard]] int pieceIndex(const std::string& name) const;
  [[nodiscard]] int jointIndex(const std::string& name) const;
  /// The number of distinct held sets (every subset of the pieces).
  [[nodiscard]] int pieceSetCount() const { return HeldPieces::setCount(static_cast<int>(pieces.size())); }
  [[nodiscard]] HeldPieces allPieces() const { return HeldPieces::fromIndex(pieceSetCount() - 1); }
  /// The held set of the named pieces: names separated by ',' or '+', or "" / "none" for none.
  /// kInvalidInput, naming the piece and the robot's own, when a name is not one of `pieces`.
  [[nodiscard]] Result<HeldPieces> piecesNamed(std::string_view names) const;
  /// "none", or the held pieces' names joined by '+' in declaration order.
  [[nodiscard]] std::string pieceSetName(HeldPieces held) const;

  /// The voltage model of both joints with these pieces held (chain.hpp; a held piece adds
  /// its mass to its link under the rigid-body model).
  [[nodiscard]] DriveModel driveModel(HeldPieces held) const;
};

}  // namespace cyber::planner

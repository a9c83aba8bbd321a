#pragma once
// The robot description the planner works on: joints, polygons, scenes, drives and settings.
// Plain values; the TOML loader (config_loader) fills and validates them.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cyber/planner/convex_polygon.hpp"
#include "cyber/planner/drive_model.hpp"
#include "cyber/planner/joint_chain.hpp"
#include "cyber/planner/topp_al_settings.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

// Polygons attached to one link of the chain, in that link's frame (joint_chain.hpp).
struct LinkGeometry {
  std::string name;
  int joint = 0;  // the link of this joint
  std::vector<ConvexPolygon> polygons;
};

// A named game piece: polygons in its joint's link frame, present only while it is held.
struct GamePiece {
  std::string name;
  int joint = 0;
  std::vector<ConvexPolygon> polygons;
};

struct NamedPolygon {
  std::string name;
  ConvexPolygon polygon;  // world frame
};

// A named set of obstacles; the first scene of a model is its default. A goal may shift the
// scene's field elements (`obstacles`) by an offset in x within offset_range_m (the robot's
// distance to them; > 0 = the robot further away); `fixed` ones (keep-outs on the robot, the
// floor) never move.
struct Scene {
  std::string name;
  std::vector<NamedPolygon> obstacles;
  std::vector<NamedPolygon> fixed;
  JointRange offset_range_m;  // {0, 0}: the scene does not move
};

struct GridSettings {
  JointVector step = JointVector(0.02, 0.02);  // cell size of each joint, joint units
};

struct SearchSettings {
  double potential_weight = 2.0;  // weight of the potential in the A* step cost
  double potential_range = 0.15;  // weighted C-space distance over which the potential decays
  // Width of a band of scene offsets that shares one set of grids, in clearances: the grids of a
  // band search the field elements swept across it, so a path may keep up to this much more than
  // the clearance near them; narrower bands cost start-up time and memory (a set of grids per
  // band; docs/algorithm.md section 2, "Scene offsets").
  double offset_band_clearances = 2.0;
};

// Eq. 8 weights for waypoints waypoint_spacing apart (the terms are plain sums, so the balance
// depends on the spacing). Tuned on the public moves: with w_p = 0.1, w_s = 10 the obstacle term
// dragged waypoints out of the obstacles' channels and bunched them (then the spline cut corners
// and fell back to the unsmoothed path), and L-BFGS needed ~40 iterations; these values keep the
// search's topology, halve the curvature integral and converge in ~4 iterations.
struct SmoothingSettings {
  double waypoint_spacing = 0.05;     // weighted C-space spacing of the optimised waypoints
  double obstacle_weight = 0.5;       // w_o  (eq. 8)
  double obstacle_decay_m = 0.03;     // d0   (eq. 8)
  double prior_weight = 20.0;         // w_p
  double length_weight = 1.0;         // w_l
  double smoothness_weight = 1000.0;  // w_s
  int max_iterations = 200;
  double gradient_tolerance = 1e-6;
  // L-BFGS also stops when a step lowers J by less than this fraction of max(1, |J|) (0: off).
  double relative_cost_tolerance = 1e-9;
  // With a start velocity v0 the path first runs straight along v0 for |v0|_Sigma * lead_in_time_s
  // (weighted length, at most max_lead_in), so a fast start does not meet a sharp bend at once.
  double lead_in_time_s = 0.1;
  double max_lead_in = 0.3;
};

struct ToppSettings {
  int grid_points = 200;                 // K
  double limit_check_step_s = 0.001;     // the continuous trajectory is checked at this step
  double limit_check_tolerance = 0.005;  // relative overshoot of a limit accepted at that check
  int max_limit_refinements = 8;         // re-solves with tightened limits after a failed check
  // Tolerances, caps and penalty schedule of the solver; [planner.topp] sets all but the L-BFGS ones.
  topp::AlSettings solver;
};

struct PlannerSettings {
  JointVector metric = JointVector(1.0, 0.1);  // diagonal of Sigma: |v|^2 = v' Sigma v
  GridSettings grid;
  SearchSettings search;
  SmoothingSettings smoothing;
  ToppSettings topp;
};

struct RobotModel {
  std::string name;
  JointChain joints;
  std::vector<LinkGeometry> links;  // at least one polygon in all
  std::vector<GamePiece> pieces;    // at most HeldPieces::kMaxPieces
  std::vector<Scene> scenes;        // scenes.front() is the default
  double clearance_m = 0.0;
  std::array<DriveParams, kJointCount> drives;
  DriveKind drive_kind = DriveKind::kFeedforward;
  // Rigid-body drives: what moves with each link's frame (index = joint), and each piece's mass
  // data by piece index (massless unless the description gives it).
  std::array<LinkInertia, kJointCount> bodies{};
  std::vector<LinkInertia> piece_inertias;
  PlannerSettings planner;

  [[nodiscard]] const JointRange& range(int joint) const { return joints[static_cast<size_t>(joint)].range; }
  [[nodiscard]] const DriveParams& drive(int joint) const { return drives[static_cast<size_t>(joint)]; }
  [[nodiscard]] bool withinLimits(const JointVector& q, double tolerance = 0.0) const {
    return range(0).contains(q[0], tolerance) && range(1).contains(q[1], tolerance);
  }
  // Index of a scene, a piece or a joint by name; -1 when there is none.
  [[nodiscard]] int sceneIndex(const std::string& name) const;
  [[nodiscard]] int pieceIndex(const std::string& name) const;
  [[nodiscard]] int jointIndex(const std::string& name) const;
  // The number of distinct held sets (every subset of the pieces).
  [[nodiscard]] int pieceSetCount() const { return HeldPieces::setCount(static_cast<int>(pieces.size())); }
  [[nodiscard]] HeldPieces allPieces() const { return HeldPieces::fromIndex(pieceSetCount() - 1); }
  // The held set of the named pieces: names separated by ',' or '+', or "" / "none" for none.
  // Nothing, with `error` naming the piece, when a name is not one of `pieces`.
  [[nodiscard]] std::optional<HeldPieces> piecesNamed(std::string_view names, std::string* error) const;
  // "none", or the held pieces' names joined by '+' in declaration order.
  [[nodiscard]] std::string pieceSetName(HeldPieces held) const;

  // The voltage model of both joints with these pieces held (drive_model.hpp; a held piece adds
  // its mass to its link under the rigid-body model).
  [[nodiscard]] DriveModel driveModel(HeldPieces held) const;
};

}  // namespace cyber::planner

#pragma once
// The path stage of algorithm.md section 2: validate the request, search the grid of the held
// game-piece set (or take the straight segment when it is clear), optimise the waypoints (eq. 8),
// interpolate them with a C^2 spline and check the spline's clearance continuously, with
// fallbacks when the check fails.
//
// Constructed once per scene and band of scene offsets: builds the collision worlds and grids of
// every game-piece set. atOffset() gives the planner of one offset in the band: the band's grids
// (conservative for every offset in it) with the exact offset's worlds, which every clearance check
// uses (docs/algorithm.md section 2, "Scene offsets"). Where the band's grid, blocked by the field
// elements swept across the band, finds no path, a grid of the exact offset's world is built for
// the request and searched instead, so that a refusal at an offset holds at that offset.
// plan() is const and keeps no state between calls, so one planner may serve several threads.

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/motion_planner.hpp"
#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/types.hpp"
#include "path/astar_search.hpp"
#include "path/cspace_grid.hpp"
#include "path/cubic_spline_path.hpp"

namespace cyber::planner {

// Whether candidates() also smooths and times the other ways to the goal it finds.
enum class PathAlternatives { kNone, kSearch };

struct PathStrategy;     // path_strategies.hpp
struct CandidateInputs;  // path_strategies.hpp

struct PlannedPath {
  std::shared_ptr<const CubicSplinePath> path;  // q(s), s in [0, length]; a GeometricPath
  std::vector<JointVector> waypoints;           // the spline's knots: exact start ... exact goal
  std::vector<JointVector> search_waypoints;    // the search (or direct) polyline before smoothing
  double search_ms = 0.0;                       // lead-in, direct check, connections, A*
  double smooth_ms = 0.0;                       // resampling, optimisation, spline, clearance check
  double min_clearance_m = std::numeric_limits<double>::infinity();  // smallest d found on the path
  bool direct = false;   // the straight segment to the goal was clear: no grid search
  bool lead_in = false;  // a straight lead-in along the start velocity was added
  // The band's grid found no path: searched on a grid of the exact offset built for this request
  // (its build is part of search_ms).
  bool exact_offset_grid = false;
  int search_expanded = 0;
  int optimizer_iterations = 0;
  PlanMethod method;  // the strategy that added it and how it was smoothed
  HeldPieces pieces;  // held along it (its collision world's, and its drives' under rigid-body dynamics)
};

class PathPlanner {
 public:
  // `band`: the scene offsets the grids serve; {0, 0} (the scene as drawn) by default.
  PathPlanner(const RobotModel& model, const Scene& scene, const JointRange& band = {});
  // The same with grids built before (the grid cache's, path/grid_cache.hpp), one per held set by
  // HeldPieces::index(); their build times are 0 (StageTimesMs::grid: none was built).
  PathPlanner(const RobotModel& model, const Scene& scene, const JointRange& band, std::vector<CSpaceGrid> grids);
  // The same grids with the worlds at scene_offset_m (inside the band). Copies the model and
  // makes the worlds: a few microseconds, no grid is built.
  [[nodiscard]] PathPlanner atOffset(double scene_offset_m) const;
  [[nodiscard]] const JointRange& band() const { return band_; }

  // start_velocity (joint units/s) only shapes the start of the path: the spline leaves along it
  // with unit Sigma-speed, after a straight lead-in. Typed errors, never an exception.
  [[nodiscard]] Result<PlannedPath> plan(const JointVector& start, const JointVector& goal, HeldPieces pieces,
                                         const JointVector& start_velocity = {}) const;
  // Every path that passed the clearance check, the one a reachability pass times fastest first
  // (the search's smoothed polyline, its shortcut, the other side of each hole of C-space, and the
  // fastest of these shaped against its time; docs/performance.md). plan() is the first.
  // Without alternatives, the search's smoothed polyline alone (a quick first look at a move).
  [[nodiscard]] Result<std::vector<PlannedPath>> candidates(
      const JointVector& start, const JointVector& goal, HeldPieces pieces, const JointVector& start_velocity = {},
      PathAlternatives alternatives = PathAlternatives::kSearch) const;
  // The first path smoothed, then the candidates of these strategies, in their order
  // (path_strategies.hpp; kSearch is every one of pathStrategies(), kNone none).
  [[nodiscard]] Result<std::vector<PlannedPath>> candidates(const JointVector& start, const JointVector& goal,
                                                            HeldPieces pieces, const JointVector& start_velocity,
                                                            std::span<const PathStrategy> strategies) const;

  [[nodiscard]] const RobotModel& model() const { return model_; }
  [[nodiscard]] const Scene& scene() const { return scene_; }
  [[nodiscard]] const CollisionWorld& world(HeldPieces pieces) const {
    return worlds_[static_cast<size_t>(pieces.index())];
  }
  [[nodiscard]] const CSpaceGrid& grid(HeldPieces pieces) const {
    return grids_->grids[static_cast<size_t>(pieces.index())];
  }
  [[nodiscard]] double gridBuildMs(HeldPieces pieces) const {
    return grids_->build_ms[static_cast<size_t>(pieces.index())];
  }

 private:
  // The steps of candidates(): the request's own errors; the lead-in along the start velocity;
  // the first path (straight or searched); the path that stays where it is; smoothing and the
  // strategies.
  [[nodiscard]] std::optional<PlanError> checkEndpoints(const JointVector& start, const JointVector& goal,
                                                        const JointVector& start_velocity,
                                                        const CollisionWorld& world) const;
  JointVector leadIn(const JointVector& start, const JointVector& start_velocity, const CollisionWorld& world,
                     std::vector<JointVector>& polyline, PlannedPath& out) const;
  // The first path's search on one grid: none when the straight segment is clear (direct), else
  // the cells A* found with its cost and connections.
  struct FirstSearch {
    bool direct = false;
    std::vector<int> cells;
    double cost = 0.0;
    std::vector<SearchEndpoint> sources, goals;
    int expanded = 0;
  };
  [[nodiscard]] Result<FirstSearch> searchFirstPath(const JointVector& start, const JointVector& from,
                                                    const JointVector& goal, const CollisionWorld& world,
                                                    const CSpaceGrid& grid) const;
  [[nodiscard]] Result<std::vector<PlannedPath>> stayingPath(const JointVector& start, double start_distance_m,
                                                             PlannedPath out) const;
  [[nodiscard]] Result<std::vector<PlannedPath>> smoothedCandidates(CandidateInputs& inputs,
                                                                    std::span<const PathStrategy> strategies) const;

  struct Grids {  // by HeldPieces::index(), shared by the planners of every offset in the band
    std::vector<CSpaceGrid> grids;
    std::vector<double> build_ms;
  };

  RobotModel model_;
  Scene scene_;
  JointRange band_;
  // Every held set's world with the scene's field elements at one offset, by HeldPieces::index().
  [[nodiscard]] std::vector<CollisionWorld> worldsAt(double scene_offset_m) const;

  std::vector<CollisionWorld> worlds_;  // by HeldPieces::index(), at one offset
  std::shared_ptr<const Grids> grids_;
};

}  // namespace cyber::planner

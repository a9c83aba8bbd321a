#pragma once
// The planner's front door: a request in, a time-optimal collision-free trajectory out.
// Chains the path stage (algorithm.md section 2) and TOPP (section 3). Built once per robot:
// the grids of every scene and game-piece set are made in create(); a request builds one only
// when the grid of its band of scene offsets finds no path, the grid of its exact offset
// (docs/algorithm.md, "2.1 Grid and potential").
// plan() is const and keeps no state between calls, so several threads may share one planner.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/trajectory.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

/// How long each stage of one plan took (docs/algorithm.md sections 2 and 3 name the stages).
struct StageTimesMs {
  double grid = 0.0;    ///< building the grid of this scene and piece set, once at create()
  double search = 0.0;  ///< this request: grid search (or the direct check), with the exact offset's grid when built
  double smooth = 0.0;  ///< this request: optimisation, spline, clearance check
  double topp = 0.0;    ///< this request: time-optimal parameterisation and its limit check
  double total = 0.0;   ///< this request, end to end (excludes the one-off grid build)
};

/// One move to plan: from a start (at rest or moving) to a goal at rest, with held pieces, in a scene.
struct PlanRequest {
  JointVector start;           ///< one value per joint (m or rad)
  JointVector goal;            ///< one value per joint (m or rad)
  JointVector start_velocity;  ///< (m/s or rad/s); empty or zero: start at rest
  HeldPieces pieces;
  int scene = 0;  ///< index into RobotModel::scenes
  /// Shift of the scene's field elements in x (> 0: the robot further from them), within the
  /// scene's offset_range_m (docs/algorithm.md section 2, "Scene offsets").
  double scene_offset_m = 0.0;
};

/// The report of the solver that timed a plan.
using SolverReport = ToppReport;

/// How a plan was made (docs/algorithm.md section 2.6): which path strategy's candidate it follows,
/// how that path became a spline, and what was done to the timed plan. Tests assert on it; logs
/// and JSON print name().
struct PlanMethod {
  /// The strategy of a path that no strategy added: the straight segment or the search's path.
  static constexpr std::string_view kFirstPath = "first path";

  /// How the path's waypoints became a spline that keeps the clearance, in the order tried.
  enum class Smoothing {
    kStraight,                ///< a clear straight segment, as it is
    kOptimised,               ///< the optimised waypoints (eq. 8)
    kStrongerObstacleWeight,  ///< optimised again with SmoothingSettings::retry_obstacle_factor
    kPrior,                   ///< the resampled polyline, not optimised
    kDensePrior,              ///< the polyline resampled four times as densely
    kShaped,                  ///< another candidate's path shaped for time (shaped_from)
    kSynchronised,            ///< the joints' own fastest motions side by side
    kStaying,                 ///< start and goal are one pose
  };

  /// What was done to make or keep the timed plan sound (a set of these bits).
  enum Repair : unsigned {
    kStoppedFirst = 1U << 0,      ///< braked along the start velocity, then planned from rest
    kLeftTheClearance = 1U << 1,  ///< out of the clearance along the steepest way, then planned
    kSlowedToAgree = 1U << 2,     ///< slowed uniformly until its 1 ms columns agree
    kGentlerStart = 1U << 3,      ///< its first acceleration made gentler until they agree
    kSlowedAfterStop = 1U << 4,   ///< the plan after a stop slowed until the joined columns agree
  };

  std::string_view strategy = kFirstPath;  ///< PathStrategy::name, or kFirstPath
  std::string_view shaped_from;            ///< kShaped: the strategy of the path that was shaped
  Smoothing smoothing = Smoothing::kOptimised;
  unsigned repairs = 0;  ///< Repair bits

  [[nodiscard]] bool has(Repair repair) const { return (repairs & repair) != 0; }
  /// One line for a person, e.g. "stop, then shortcut (optimised), slowed to agree at 1 ms".
  [[nodiscard]] std::string name() const;
  friend bool operator==(const PlanMethod&, const PlanMethod&) = default;
};

/// A planned move: its trajectory, the path it follows and how it was found.
struct Plan {
  std::shared_ptr<const Trajectory> trajectory;
  std::vector<JointVector> waypoints;  ///< the spline's knots, exact start to exact goal
  StageTimesMs times_ms;
  SolverReport solver;
  double min_clearance_m = 0.0;  ///< smallest distance to an obstacle found along the path
  PlanMethod method;             ///< how the path was found and the plan made sound
};

/// Which grids create() builds: every one (the daemon, which must answer any goal without
/// building one), or only those one move needs (cyber-plan, whose start-up is most of its run).
struct GridSelection {
  int scene = -1;                        ///< -1: every scene
  std::optional<double> scene_offset_m;  ///< set: only the grids of this offset; unset: every band
};

class PathPlanner;  ///< the path stage of one scene (internal)

/// Plans the motions of one robot. Cheap to copy (its grids are shared, never changed after create()).
class MotionPlanner {
 public:
  /// Builds the path planners (and grids) of every scene. Fails with kInvalidInput when the model
  /// has no scene or no arm geometry. `cache_dir`, when set, is the grid cache's folder
  /// (docs/design.md, "The grid cache"): grids are read from it when their files check, else
  /// built and stored there; a folder that cannot be written only costs the time.
  static Result<MotionPlanner> create(const RobotModel& model, const GridSelection& selection = GridSelection{},
                                      const std::optional<std::filesystem::path>& cache_dir = std::nullopt);

  /// The fastest collision-free motion from the request's start (at rest or moving) to its goal,
  /// ending at rest; or why there is none (PlanStatus).
  [[nodiscard]] Result<Plan> plan(const PlanRequest& request) const;

  /// The fastest admissible stop from the request's start along its start velocity, in the world
  /// of its scene, offset and held pieces (the goal is not used): what a cancel brakes with
  /// (docs/moving-starts.md). Errors: kInvalidInput (unknown scene, velocity zero or not finite),
  /// kInfeasibleStart (no stop before a joint limit), kClearanceNotMet, and the solver's.
  [[nodiscard]] Result<Plan> stop(const PlanRequest& request) const;

  /// The robot description the planner was built from.
  [[nodiscard]] const RobotModel& model() const;
  /// The bands of scene offsets a scene's grids were built for (the first is the offset 0 alone).
  [[nodiscard]] std::vector<JointRange> offsetBands(int scene) const;

 private:
  struct Scenes;
  friend const PathPlanner& drawnPathPlanner(const MotionPlanner& planner, int scene);
  explicit MotionPlanner(std::shared_ptr<const Scenes> scenes) : scenes_(std::move(scenes)) {}
  std::shared_ptr<const Scenes> scenes_;
};

}  // namespace cyber::planner

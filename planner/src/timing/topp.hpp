#pragma once
// Time-optimal path parameterisation (algorithm.md section 3): the fastest traversal of a
// geometric path under the voltage, current (and optional velocity/acceleration) limits of both
// drives, starting with path speed^2 b_start and ending at rest.

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/trajectory.hpp"
#include "cyber/planner/types.hpp"
#include "timing/topp_augmented_lagrangian.hpp"
#include "timing/topp_problem.hpp"

namespace cyber::planner {

// Reusable solver: keeps its buffers between calls. MotionPlanner makes one for a plan's candidate
// paths and one for its stop (a plan is not on the streaming path, so it may allocate), which keeps
// MotionPlanner::plan const and free of shared state.
class ToppSolver {
 public:
  explicit ToppSolver(ToppSettings settings = {}) : settings_(settings) {}

  // b_start = |v0|_Sigma^2 when the path starts along the start velocity v0 with |q'(0)|_Sigma = 1
  // (0 at rest); the trajectory always ends at rest. Errors: kInvalidInput (null/non-finite
  // path, bad b_start or drive figures, limits that cannot hold on the path), kInfeasibleStart
  // (b_start cannot be brought to rest within the limits, even allowing limit_check_tolerance on
  // the start speed; see ToppReport::start_speed_ratio), kSolverNotConverged (the augmented
  // Lagrangian or the limit refinement hit its cap; the reason gives the residuals).
  Result<Trajectory> solve(std::shared_ptr<const GeometricPath> path, const DriveModel& drives, double b_start = 0.0,
                           ToppReport* report = nullptr);

  [[nodiscard]] const ToppSettings& settings() const { return settings_; }

 private:
  // The steps of solve() (topp.cpp; algorithm.md section 3, "Stopping rules").
  struct Move;
  struct Attempt;
  enum class GridChange;
  enum class RowLimits;
  Result<Done> sampleRows(const Move& move, int grid_points, ToppReport& report);
  Result<Done> sampleTimedRows(const Move& move, int grid_points, ToppReport& report);
  Result<GridChange> refineGrid(const Move& move, ToppReport& report);
  Result<double> warmStart(const Move& move, bool first, ToppReport& report);
  Result<Trajectory> solvedTrajectory(const Move& move, double time_scale) const;
  Attempt solveRows(const Move& move, const topp::AlSettings& al, bool first, ToppReport& report);
  Result<RowLimits> refineOrTighten(const Move& move, ToppReport& report);

  ToppSettings settings_;
  topp::Problem problem_;  // unit length, seconds
  topp::Problem scaled_;   // unit length, time in units of the warm start's duration
  topp::LimitMargins margins_;
  std::vector<double> profile_;
  std::vector<double> controllable_;
  // A coarse grid's reachability profile, which places the move's grids partly evenly in time
  // (topp::sampleGrid); timed_ is false until it exists for the current move.
  std::vector<double> timing_s_;
  std::vector<double> timing_b_;
  bool timed_ = false;
  topp::AlState state_;
  topp::AlWorkspace workspace_;
};

// One-shot convenience wrapper around ToppSolver.
Result<Trajectory> parameterizeTimeOptimal(std::shared_ptr<const GeometricPath> path, const DriveModel& drives,
                                           const ToppSettings& settings, double b_start = 0.0,
                                           ToppReport* report = nullptr);

}  // namespace cyber::planner

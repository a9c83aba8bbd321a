#pragma once
// The discretised time-optimal parameterisation problem of algorithm.md section 3: the grid
// s_0 < ... < s_{K-1}, the path samples on it, and every limit as a linear inequality in
// (a_k, b_n, c_n) with c_n = sqrt(b_n).
//
// Each interval k carries one constant path acceleration a_k (b linear in s in between), so each
// limit is imposed at BOTH ends of the interval with that interval's a_k: the trajectory between
// grid points then only deviates from the limits by the curvature of the path and of sqrt(b).

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/trajectory.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner::topp {

enum class LimitKind : std::uint8_t { kVoltage = 0, kCurrent = 1, kAcceleration = 2, kVelocity = 3 };
inline constexpr int kLimitKindCount = 4;

// A limit on interval k at the fraction `at` of the way from node k to node k+1 (0, 1/2 or 1):
// lo <= alpha a_k + beta b_at + gamma c_at <= hi, b_at = (1 - at) b_k + at b_{k+1} (exact: b is
// linear in s), c_at likewise (the chord of sqrt(b), exact at the nodes). Divided by the size of
// its limit so every row is of order one; lo may be -infinity (one-sided rows).
struct LinearRow {
  int interval = 0;
  double at = 0.0;
  double alpha = 0.0;
  double beta = 0.0;
  double gamma = 0.0;
  double lo = 0.0;
  double hi = 0.0;
  std::int8_t joint = 0;
  LimitKind kind = LimitKind::kVoltage;

  [[nodiscard]] double value(double a, double b0, double b1, double c0, double c1) const {
    return alpha * a + beta * ((1.0 - at) * b0 + at * b1) + gamma * ((1.0 - at) * c0 + at * c1);
  }
};

// Per interval, joint and kind: how much the limit is lowered (volts for voltage, R*amps for
// current, joint units for acceleration and velocity). Filled when the continuous check finds
// the trajectory between grid points over a limit (topp.cpp).
class LimitMargins {
 public:
  void reset(int intervals) { values_.assign(static_cast<size_t>(intervals) * kMaxJoints * kLimitKindCount, 0.0); }
  [[nodiscard]] double get(int interval, int joint, LimitKind kind) const {
    return values_.empty() ? 0.0 : values_[index(interval, joint, kind)];
  }
  double& at(int interval, int joint, LimitKind kind) { return values_[index(interval, joint, kind)]; }

 private:
  static size_t index(int interval, int joint, LimitKind kind) {
    return (static_cast<size_t>(interval) * kMaxJoints + static_cast<size_t>(joint)) * kLimitKindCount +
           static_cast<size_t>(kind);
  }
  std::vector<double> values_;
};

// No path speed ds/dt above this is searched for (path units/s): far beyond any motor's reach, it
// only bounds the reachability search.
inline constexpr double kSpeedBound = 1e3;

// C_k is a cap for the forward pass and the optimiser absorbs what lies below it, so the backward
// pass bisects it to this relative width only (topp_reachability.cpp).
inline constexpr double kControllableTolerance = 1e-5;

// kSpeedBound in the units of the unit-length problem of a path `length` long.
inline double unitSpeedBound(double length) { return kSpeedBound / length; }

// Units: the grid runs over s/L in [0, 1] (L the path length), so b is (ds/dt)^2 / L^2 and the
// path derivatives are scaled to match (q' L, q'' L^2); scaleTime() further measures time in
// units of a time scale. The optimiser then sees numbers of order one for any path.
struct Problem {
  std::vector<double> s;                  // K grid points, s[0] = 0, s[K-1] = 1
  std::vector<PathPoint> points;          // path samples at s
  std::vector<PathPoint> midpoints;       // path samples halfway between consecutive grid points
  std::vector<double> density_workspace;  // sampleGrid's buffers
  std::vector<double> time_workspace;
  std::vector<LinearRow> rows;  // sorted by interval
  std::vector<int> row_begin;   // rows of interval k: [row_begin[k], row_begin[k+1])
  double b_start = 0.0;
  double b_end = 0.0;
  // The cost sum 2 ds_k d_k is multiplied by this (1 / duration of the warm start): the same
  // problem, with multipliers of the same size whatever the length of the path.
  double cost_scale = 1.0;
  // No speed c = sqrt(b) above this is searched for (in the problem's units; unitSpeedBound).
  double speed_bound = kSpeedBound;
  // The backward pass bisects each C_k to this relative width (a cap for the forward pass).
  double controllable_tolerance = kControllableTolerance;
  [[nodiscard]] int gridPoints() const { return static_cast<int>(s.size()); }
  [[nodiscard]] int intervals() const { return gridPoints() - 1; }
  [[nodiscard]] double ds(int k) const { return s[static_cast<size_t>(k) + 1] - s[static_cast<size_t>(k)]; }
};

// A speed profile on the unit-length path: b (K values, b linear in s between the nodes s).
struct ProfileView {
  const std::vector<double>* s = nullptr;
  const std::vector<double>* b = nullptr;
  double time_share = ToppSettings{}.time_grid_share;         // of the grid placed evenly in time
  double max_time_density = ToppSettings{}.max_time_density;  // of a cell, in mean times
};

// Samples the path (length > 0) on `grid_points` (>= 2) points, denser where the path bends,
// normalised to unit length: s in [0, 1], q' multiplied by the length, q'' by its square.
// With a speed profile (a first pass over the same path), timing.time_share of the points (40 %)
// are placed evenly in the profile's time instead: the slow ends of a rest-to-rest move, where the limits change
// fastest in time, get more of the points than a grid even in s gives them (algorithm.md
// section 3, "Grid").
void sampleGrid(const GeometricPath& path, int grid_points, Problem& problem, ProfileView timing = {});

// `out` = `in` with time measured in units of time_scale_s: b and c^2 scale by T^2, a by T^2.
// Copies grid and rows (no path samples); the cost sum 2 ds d becomes the duration divided by T.
void scaleTime(const Problem& in, double time_scale_s, Problem& out);

// Builds the limit rows of algorithm.md section 3 for the sampled grid, at both ends and the
// middle of every interval. The Coulomb term kS*sgn(qdot) uses every sign qdot takes on the
// interval (both when q'_j changes sign in it, 0 at a node where the profile is pinned at rest).
// kInvalidInput, naming the limit and where, when a limit cannot hold whatever the motion (e.g.
// gravity alone needs more than the voltage limit).
Result<Done> buildRows(const DriveModel& drives, const LimitMargins& margins, Problem& problem);

// The trajectory along `path` of a speed profile on `problem`'s unit-length grid: s scales by the
// path's length and b by b_scale (the length squared, over the time scale squared when time was
// scaled). unit_b(k) is the profile at node k, clamped at 0. The ends are set exactly: to b_start,
// the move's own (scaling it there and back would round it), and to rest.
template <class UnitB>
Result<Trajectory> unitProfileTrajectory(std::shared_ptr<const GeometricPath> path, const DriveModel& drives,
                                         const Problem& problem, UnitB&& unit_b, double b_scale, double b_start) {
  const double length = path->length();
  std::vector<double> s_grid(problem.s.size()), b_grid(problem.s.size());
  for (size_t k = 0; k < s_grid.size(); ++k) {
    s_grid[k] = problem.s[k] * length;
    b_grid[k] = std::max(0.0, unit_b(k)) * b_scale;
  }
  s_grid.back() = length;
  b_grid.front() = b_start;
  b_grid.back() = 0.0;
  return Trajectory::create(std::move(path), drives, std::move(s_grid), std::move(b_grid));
}

}  // namespace cyber::planner::topp

#include "cyber/planner/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

namespace cyber::planner {
namespace {

// The grid's last s may differ from the path's length by the roundoff of summing its steps.
constexpr double kGridEndRoundoff = 1e-9;

// Of ToppSettings::limit_check_tolerance accepted by withinDriveLimits(trajectory, settings).
constexpr double kOwnCheckShare = 0.5;

}  // namespace

Result<Trajectory> Trajectory::create(std::shared_ptr<const GeometricPath> path, const DriveModel& drives,
                                      std::vector<double> s_grid, std::vector<double> b_grid) {
  if (!path) return Result<Trajectory>::failure(PlanStatus::kInvalidInput, "trajectory without a path");
  const double length = path->length();
  if (!std::isfinite(length) || length < 0.0) {
    return Result<Trajectory>::failure(PlanStatus::kInvalidInput, "path length is not a finite non-negative number");
  }
  if (s_grid.empty() || s_grid.size() != b_grid.size()) {
    return Result<Trajectory>::failure(PlanStatus::kInvalidInput, "grid and profile sizes differ or are empty");
  }
  const size_t n = s_grid.size();
  if (n == 1 && (length != 0.0 || s_grid[0] != 0.0 || b_grid[0] != 0.0)) {
    return Result<Trajectory>::failure(PlanStatus::kInvalidInput,
                                       "a single grid point is only valid for a zero-length path at rest");
  }
  if (n > 1 && (s_grid.front() != 0.0 || std::abs(s_grid.back() - length) > kGridEndRoundoff * std::max(1.0, length))) {
    return Result<Trajectory>::failure(PlanStatus::kInvalidInput, "grid does not span [0, path length]");
  }
  for (size_t k = 0; k < n; ++k) {
    if (!std::isfinite(s_grid[k]) || !std::isfinite(b_grid[k]) || b_grid[k] < 0.0) {
      return Result<Trajectory>::failure(PlanStatus::kInvalidInput,
                                         fmt::format("profile value {} is negative or not finite", k));
    }
    if (k > 0 && !(s_grid[k] > s_grid[k - 1])) {
      return Result<Trajectory>::failure(PlanStatus::kInvalidInput, "grid is not strictly increasing");
    }
  }

  Trajectory trajectory;
  trajectory.path_ = std::move(path);
  trajectory.drives_ = drives;
  trajectory.t_grid_.assign(n, 0.0);
  trajectory.a_grid_.assign(n > 1 ? n - 1 : 0, 0.0);
  for (size_t k = 0; k + 1 < n; ++k) {
    const double ds = s_grid[k + 1] - s_grid[k];
    const double speed_sum = std::sqrt(b_grid[k]) + std::sqrt(b_grid[k + 1]);
    if (!(speed_sum > 0.0)) {
      return Result<Trajectory>::failure(PlanStatus::kInvalidInput,
                                         fmt::format("profile is at rest over interval {}", k));
    }
    trajectory.a_grid_[k] = (b_grid[k + 1] - b_grid[k]) / (2.0 * ds);
    trajectory.t_grid_[k + 1] = trajectory.t_grid_[k] + 2.0 * ds / speed_sum;  // exact for constant a
  }
  trajectory.s_grid_ = std::move(s_grid);
  trajectory.b_grid_ = std::move(b_grid);
  return trajectory;
}

size_t Trajectory::intervalAtTime(double t) const {
  const auto it = std::upper_bound(t_grid_.begin(), t_grid_.end(), t);
  const size_t k = it == t_grid_.begin() ? 0 : static_cast<size_t>(it - t_grid_.begin()) - 1;
  return std::min(k, t_grid_.size() - 2);
}

size_t Trajectory::intervalAtS(double s) const {
  const auto it = std::upper_bound(s_grid_.begin(), s_grid_.end(), s);
  const size_t k = it == s_grid_.begin() ? 0 : static_cast<size_t>(it - s_grid_.begin()) - 1;
  return std::min(k, s_grid_.size() - 2);
}

TrajectorySample Trajectory::sample(double t) const {
  TrajectorySample out = sampleMotion(t);
  out.volts = drives_.volts(out.q, out.qdot, out.qddot);
  out.amps = drives_.amps(out.volts, out.qdot);
  return out;
}

TrajectorySample Trajectory::sampleMotion(double t) const {
  TrajectorySample out;
  const double duration = duration_s();
  const bool holding = !(t <= duration);  // after the end (or NaN): hold the goal at rest
  out.t = holding ? duration : std::max(0.0, t);
  if (s_grid_.size() >= 2 && !holding) {
    const size_t k = intervalAtTime(out.t);
    const double tau = std::max(0.0, out.t - t_grid_[k]);
    const double v0 = std::sqrt(b_grid_[k]);
    const double a = a_grid_[k];
    out.sdot = std::max(0.0, v0 + a * tau);
    out.s = std::clamp(s_grid_[k] + v0 * tau + 0.5 * a * tau * tau, s_grid_[k], s_grid_[k + 1]);
    out.sddot = a;
  } else {
    out.s = s_grid_.empty() ? 0.0 : s_grid_.back();
  }
  const PathPoint p = path_->at(out.s);
  out.q = p.q;
  out.qdot = p.dq_ds * out.sdot;
  out.qddot = p.d2q_ds2 * (out.sdot * out.sdot) + p.dq_ds * out.sddot;  // eq. 11: q'' b + q' a
  return out;
}

double Trajectory::timeAt(double s) const {
  if (s_grid_.size() < 2) return 0.0;
  s = std::clamp(s, 0.0, s_grid_.back());
  const size_t k = intervalAtS(s);
  const double ds = s - s_grid_[k];
  const double b = std::max(0.0, b_grid_[k] + 2.0 * a_grid_[k] * ds);
  const double speed_sum = std::sqrt(b_grid_[k]) + std::sqrt(b);
  return speed_sum > 0.0 ? t_grid_[k] + 2.0 * ds / speed_sum : t_grid_[k];
}

double Trajectory::pathParameterAt(double t) const {
  if (s_grid_.size() < 2) return 0.0;
  t = std::clamp(t, 0.0, duration_s());
  const size_t k = intervalAtTime(t);
  const double tau = t - t_grid_[k];
  return std::clamp(s_grid_[k] + std::sqrt(b_grid_[k]) * tau + 0.5 * a_grid_[k] * tau * tau, s_grid_[k],
                    s_grid_[k + 1]);
}

bool withinDriveLimits(const Trajectory& trajectory, double step_s, double tolerance) {
  bool within = true;
  forEachLimitSample(trajectory, step_s, [&](double, int, DriveLimit, double value, double limit) {
    if (std::abs(value) > limit * (1.0 + tolerance)) within = false;
  });
  return within;
}

bool withinDriveLimits(const Trajectory& trajectory, const ToppSettings& settings) {
  return withinDriveLimits(trajectory, settings.limit_check_step_s, kOwnCheckShare * settings.limit_check_tolerance);
}

Result<Trajectory> slowedDown(const Trajectory& trajectory, double factor) {
  if (!(factor >= 1.0) || !std::isfinite(factor)) {
    return Result<Trajectory>::failure(PlanStatus::kInvalidInput, "a trajectory is slowed down by a factor >= 1");
  }
  std::vector<double> b_grid = trajectory.bGrid();
  for (double& b : b_grid) b /= factor * factor;
  return Trajectory::create(trajectory.sharedPath(), trajectory.drives(), trajectory.sGrid(), std::move(b_grid));
}

Result<Trajectory> gentlerStart(const Trajectory& trajectory, double scale) {
  using R = Result<Trajectory>;
  if (!(scale > 0.0 && scale <= 1.0))
    return R::failure(PlanStatus::kInvalidInput, "a start is made gentler by 0 < scale <= 1");
  const std::vector<double>& s_grid = trajectory.sGrid();
  const std::vector<double>& b_grid = trajectory.bGrid();
  if (s_grid.size() < 2 || b_grid.front() != 0.0) {
    return R::failure(PlanStatus::kInvalidInput, "only a trajectory from rest has a gentler start");
  }
  const double slope = scale * b_grid[1] / s_grid[1];  // db/ds of the line: 2 scale a_0
  std::vector<double> s_out{s_grid[0]}, b_out{0.0};
  size_t k = 1;
  // Knots where the line is below the profile take the line's value.
  for (; k < s_grid.size() && slope * s_grid[k] < b_grid[k]; ++k) {
    s_out.push_back(s_grid[k]);
    b_out.push_back(slope * s_grid[k]);
  }
  if (k == s_grid.size()) return R::failure(PlanStatus::kInvalidInput, "the line never meets the profile");
  // The line meets the profile inside (s_{k-1}, s_k]: b_{k-1} + m (s - s_{k-1}) = slope s.
  const double m = (b_grid[k] - b_grid[k - 1]) / (s_grid[k] - s_grid[k - 1]);
  if (slope > m) {
    const double s_meet = (b_grid[k - 1] - m * s_grid[k - 1]) / (slope - m);
    if (s_meet > s_out.back() && s_meet < s_grid[k]) {
      s_out.push_back(s_meet);
      b_out.push_back(slope * s_meet);
    }
  }
  s_out.insert(s_out.end(), s_grid.begin() + static_cast<long>(k), s_grid.end());
  b_out.insert(b_out.end(), b_grid.begin() + static_cast<long>(k), b_grid.end());
  return Trajectory::create(trajectory.sharedPath(), trajectory.drives(), std::move(s_out), std::move(b_out));
}

}  // namespace cyber::planner

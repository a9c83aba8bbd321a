#include "timing/topp.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "timing/topp_reachability.hpp"

namespace cyber::planner {
namespace {

using topp::LimitKind;

constexpr int kMinGridPoints = 3;  // rest to rest needs one node in between

bool positiveFinite(double v) { return std::isfinite(v) && v > 0.0; }

bool validDrive(const DriveParams& d, int joint, std::string* error) {
  const MotorParams& m = d.motor;
  const bool ok = positiveFinite(m.nominal_voltage_volts) && positiveFinite(m.stall_current_amps) &&
                  positiveFinite(m.free_speed_radps) && std::isfinite(m.free_current_amps) &&
                  positiveFinite(m.kvRadpsPerVolt()) && positiveFinite(d.gearing) && d.motor_count >= 1 &&
                  std::isfinite(d.kS_volts) && d.kS_volts >= 0.0 && std::isfinite(d.kG_volts) && std::isfinite(d.kV) &&
                  d.kV >= 0.0 && std::isfinite(d.kA) && d.kA >= 0.0 && positiveFinite(d.voltage_limit_volts) &&
                  positiveFinite(d.current_limit_amps) && (!d.velocity_limit || positiveFinite(*d.velocity_limit)) &&
                  (!d.acceleration_limit || positiveFinite(*d.acceleration_limit));
  if (!ok) *error = fmt::format("the drive figures of joint {} are not finite and positive where required", joint);
  return ok;
}

std::string residualText(const topp::AlReport& r) {
  return fmt::format("primal residual {:.3g}, dual residual {:.3g} after {} outer / {} inner iterations",
                     r.primal_residual, r.dual_residual, r.outer_iterations, r.inner_iterations);
}

void accumulate(ToppReport& report, const topp::AlReport& r) {
  report.outer_iterations += r.outer_iterations;
  report.inner_iterations += r.inner_iterations;
  report.evaluations += r.evaluations;
  report.primal_residual = r.primal_residual;
  report.dual_residual = r.dual_residual;
  report.penalty = r.penalty;
}

double profileDuration(const topp::Problem& problem, const std::vector<double>& b) {
  double t = 0.0;
  for (int k = 0; k < problem.intervals(); ++k) {
    t += 2.0 * problem.ds(k) / (std::sqrt(b[static_cast<size_t>(k)]) + std::sqrt(b[static_cast<size_t>(k) + 1]));
  }
  return t;
}

// The optimiser's row kind of a drive limit, and the report's peak ratio it raises.
struct KindAndPeak {
  LimitKind kind;
  double& peak;
};
KindAndPeak kindAndPeak(DriveLimit limit, ToppReport& report) {
  switch (limit) {
    case DriveLimit::kVoltage: return {LimitKind::kVoltage, report.peak_voltage_ratio};
    case DriveLimit::kCurrent: return {LimitKind::kCurrent, report.peak_current_ratio};
    case DriveLimit::kVelocity: return {LimitKind::kVelocity, report.peak_velocity_ratio};
    case DriveLimit::kAcceleration: break;
  }
  return {LimitKind::kAcceleration, report.peak_acceleration_ratio};
}

// Samples the trajectory every limit_check_step_s (and at its end) and raises the margins of every
// interval where a limit is exceeded by more than half the accepted overshoot. Returns true when
// no sample exceeds a limit by more than that. Fills the peak ratios of the report.
bool checkLimits(const Trajectory& trajectory, const ToppSettings& settings, topp::LimitMargins& margins,
                 ToppReport& report) {
  // Accept only a share of the tolerance at the check's own sample times, so that sampling at
  // other instants (the streamer's, a verifier's) stays within the whole tolerance.
  const double tolerance = settings.check_share * settings.limit_check_tolerance;
  const std::vector<double>& t_grid = trajectory.tGrid();
  report.peak_voltage_ratio = report.peak_current_ratio = 0.0;
  report.peak_velocity_ratio = report.peak_acceleration_ratio = 0.0;

  bool within = true;
  struct Excess {
    int interval, joint;
    LimitKind kind;
    double amount;
    double limit;
  };
  // Few intervals exceed at once; a small fixed buffer would do, but the count is unbounded.
  std::vector<Excess> excesses;
  size_t k = 0;
  forEachLimitSample(trajectory, settings.limit_check_step_s,
                     [&](double t, int j, DriveLimit which, double value, double limit) {
                       while (k + 2 < t_grid.size() && t_grid[k + 1] <= t) ++k;
                       const auto [kind, peak] = kindAndPeak(which, report);
                       const double ratio = std::abs(value) / limit;
                       peak = std::max(peak, ratio);
                       if (ratio > 1.0 + tolerance) within = false;
                       if (ratio > 1.0 + 0.5 * tolerance) {
                         excesses.push_back({static_cast<int>(k), j, kind, std::abs(value) - limit, limit});
                       }
                     });
  if (!within) {
    // The bulge between the grid points stays about the same when the limits at the ends move,
    // so lowering the end limits by the excess (plus a little) brings the peak to the limit.
    for (const Excess& e : excesses) {
      double& margin = margins.at(e.interval, e.joint, e.kind);
      margin = std::min(margin + settings.margin_overshoot * e.amount + settings.margin_floor * e.limit,
                        settings.max_margin * e.limit);
    }
  }
  return within;
}

Result<Trajectory> fail(PlanStatus status, std::string reason) {
  return Result<Trajectory>::failure(status, std::move(reason));
}

// The reason the inputs cannot be parameterised, if any (the path itself is known to exist).
std::optional<std::string> invalidInput(double length, double b_start, const DriveModel& drives) {
  if (!std::isfinite(length) || length < 0.0) return "path length is not finite";
  if (!std::isfinite(b_start) || b_start < 0.0) return "start path speed^2 b_start must be finite and >= 0";
  std::string error;
  for (int j = 0; j < drives.jointCount(); ++j) {
    if (!validDrive(drives.drive(j), j, &error)) return error;
  }
  return std::nullopt;
}

// The problem is normalised to unit length, so short paths need no special grid.
int initialGridPoints(const ToppSettings& settings) { return std::max(kMinGridPoints, settings.grid_points); }
int finestGridPoints(const ToppSettings& settings) {
  return std::max(initialGridPoints(settings), settings.max_grid_factor * settings.grid_points);
}

// Relative overshoot of the worst limit at the continuous check's samples.
double peakOvershoot(const ToppReport& report) {
  return std::max({report.peak_voltage_ratio, report.peak_current_ratio, report.peak_velocity_ratio,
                   report.peak_acceleration_ratio}) -
         1.0;
}

std::string overLimitsText(int refinements, const ToppReport& report) {
  return fmt::format(
      "limits still exceeded between grid points after {} refinements (peak voltage {:.4f}, current {:.4f} of the "
      "limit)",
      refinements, report.peak_voltage_ratio, report.peak_current_ratio);
}

}  // namespace

// What one call of solve() asks for: a path of non-zero length, its drives and its start.
struct ToppSolver::Move {
  std::shared_ptr<const GeometricPath> path;
  DriveModel drives;
  double length = 0.0;
  double length_squared = 0.0;
  double b_start = 0.0;       // as asked, in path units
  double unit_b_start = 0.0;  // on the unit-length path the problem is solved on: b_start / length^2
};

// How one solve of the current rows ended; `result` holds the trajectory or the failure.
struct ToppSolver::Attempt {
  enum class End {
    kWithinLimits,  // the trajectory passed the continuous check: the answer
    kOverLimits,    // the trajectory exceeds a limit between grid points; margins_ are raised there
    kHard,          // the warm start or the solver failed on these rows (a finer grid may help)
    kBroken,        // an invariant of the solver failed
  };
  End end;
  Result<Trajectory> result;
};

enum class ToppSolver::GridChange { kRefined, kFinest };

// Whether the rows carry margins from a failed continuous check.
enum class ToppSolver::RowLimits { kAsGiven, kTightened };

// Samples the path on `grid_points` points and builds the rows without margins.
Result<Done> ToppSolver::sampleRows(const Move& move, int grid_points, ToppReport& report) {
  report.grid_points = grid_points;
  topp::sampleGrid(
      *move.path, grid_points, problem_,
      timed_ ? topp::ProfileView{&timing_s_, &timing_b_, settings_.time_grid_share, settings_.max_time_density}
             : topp::ProfileView{});
  for (const PathPoint& p : problem_.points) {
    if (!p.q.allFinite() || !p.dq_ds.allFinite() || !p.d2q_ds2.allFinite()) {
      return PlanError{PlanStatus::kInvalidInput, "the path returns non-finite values"};
    }
  }
  margins_.reset(problem_.intervals());
  return topp::buildRows(move.drives, margins_, problem_);
}

// Samples the grid again, partly evenly in the time of the reachability profile of a coarse
// first grid: the time lost to one constant a per interval grows with the interval's duration,
// which on a grid even in s is largest at the slow ends of the move. The coarse profile's time
// is close enough to place points and costs a fraction of a pass on the full grid. Without a
// profile the grid stays even in s (the warm start then reports why).
Result<Done> ToppSolver::sampleTimedRows(const Move& move, int grid_points, ToppReport& report) {
  timed_ = false;
  if (!sampleRows(move, std::min(grid_points, settings_.timing_grid_points), report)) {
    return sampleRows(move, grid_points, report);
  }
  problem_.b_start = move.unit_b_start;
  const topp::ReachabilityResult reach =
      topp::forwardBackward(problem_, profile_, controllable_, settings_.limit_check_tolerance);
  if (reach.status == topp::ReachabilityStatus::kOk) {
    timing_s_ = problem_.s;
    timing_b_ = profile_;
    timed_ = true;
  }
  return sampleRows(move, grid_points, report);
}

// Halves every interval, up to finestGridPoints(): between closer grid points the trajectory
// stays closer to the limits it meets at them. The new rows carry no margins.
Result<ToppSolver::GridChange> ToppSolver::refineGrid(const Move& move, ToppReport& report) {
  const int points = std::min(finestGridPoints(settings_), 2 * problem_.gridPoints() - 1);
  if (points <= problem_.gridPoints()) return GridChange::kFinest;
  if (auto rows = sampleRows(move, points, report); !rows) return rows.error();
  return GridChange::kRefined;
}

// Warm start (algorithm.md section 3): the reachability profile of the current rows, and the
// multipliers that make it stationary, in scaled_ and state_. Repeated for every attempt: a
// feasible start is cheaper to polish than a stale one. Returns the time scale of scaled_.
Result<double> ToppSolver::warmStart(const Move& move, bool first, ToppReport& report) {
  problem_.b_start = move.unit_b_start;
  const topp::ReachabilityResult reach =
      topp::forwardBackward(problem_, profile_, controllable_, settings_.limit_check_tolerance);
  if (reach.status != topp::ReachabilityStatus::kOk) {
    const PlanStatus status = reach.status == topp::ReachabilityStatus::kStartNotControllable
                                  ? PlanStatus::kInfeasibleStart
                                  : PlanStatus::kInvalidInput;
    return Result<double>::failure(status, reach.reason);
  }
  if (first) report.controllable_start_b = reach.controllable_start_b * move.length_squared;
  problem_.b_start = reach.start_b;
  report.start_speed_ratio = move.unit_b_start > 0.0 ? std::sqrt(reach.start_b / move.unit_b_start) : 1.0;
  // Time in units of the warm start's duration: the optimiser sees a duration of about one.
  const double warm_duration = profileDuration(problem_, profile_);
  if (first) report.warm_start_duration_s = warm_duration;
  const double time_scale = warm_duration > 0.0 && std::isfinite(warm_duration) ? warm_duration : 1.0;
  topp::scaleTime(problem_, time_scale, scaled_);
  for (double& b : profile_) b *= time_scale * time_scale;
  topp::initialGuess(scaled_, profile_, state_.x);
  topp::estimateMultipliers(scaled_, state_.x, state_.multipliers);
  state_.penalty = 0.0;
  return time_scale;
}

// The solution in state_ back in path units: b = (ds/dt)^2 = b_scaled length^2 / T^2.
Result<Trajectory> ToppSolver::solvedTrajectory(const Move& move, double time_scale) const {
  const topp::VariableLayout layout{problem_.gridPoints()};
  const double b_start = problem_.b_start == move.unit_b_start ? move.b_start : problem_.b_start * move.length_squared;
  return topp::unitProfileTrajectory(
      move.path, move.drives, problem_, [&](size_t k) { return state_.x[layout.b(static_cast<int>(k))]; },
      move.length_squared / (time_scale * time_scale), b_start);
}

// One attempt on the current rows: warm start, augmented Lagrangian, continuous check.
ToppSolver::Attempt ToppSolver::solveRows(const Move& move, const topp::AlSettings& al, bool first,
                                          ToppReport& report) {
  const Result<double> time_scale = warmStart(move, first, report);
  if (!time_scale) return {Attempt::End::kHard, time_scale.error()};
  const topp::AlReport solved = topp::solveAugmentedLagrangian(scaled_, al, state_, workspace_);
  accumulate(report, solved);
  if (!solved.converged) {
    return {Attempt::End::kHard, PlanError{PlanStatus::kSolverNotConverged,
                                           "time-optimal parameterisation did not converge: " + residualText(solved)}};
  }
  Result<Trajectory> trajectory = solvedTrajectory(move, time_scale.value());
  if (!trajectory) {
    return {Attempt::End::kBroken,
            PlanError{PlanStatus::kInternalError,
                      "the solved profile is not a valid trajectory: " + trajectory.error().message}};
  }
  const bool within = checkLimits(trajectory.value(), settings_, margins_, report);
  return {within ? Attempt::End::kWithinLimits : Attempt::End::kOverLimits, std::move(trajectory)};
}

// After a continuous check over the limits (margins_ raised where it failed): a large overshoot
// is met with a finer grid, a small one (or one on the finest grid) by lowering the limits of the
// intervals concerned; limits that can no longer hold once lowered get a finer grid instead.
Result<ToppSolver::RowLimits> ToppSolver::refineOrTighten(const Move& move, ToppReport& report) {
  Result<GridChange> change =
      peakOvershoot(report) > settings_.refine_above ? refineGrid(move, report) : GridChange::kFinest;
  if (!change) return change.error();
  if (change.value() == GridChange::kRefined) return RowLimits::kAsGiven;
  const Result<Done> tightened = topp::buildRows(move.drives, margins_, problem_);
  if (tightened) return RowLimits::kTightened;
  change = refineGrid(move, report);
  if (!change) return change.error();
  if (change.value() == GridChange::kRefined) return RowLimits::kAsGiven;
  return tightened.error();
}

Result<Trajectory> ToppSolver::solve(std::shared_ptr<const GeometricPath> path, const DriveModel& drives,
                                     double b_start, ToppReport* report_out) {
  ToppReport local_report;
  ToppReport& report = report_out ? *report_out : local_report;
  report = ToppReport{};

  if (!path) return fail(PlanStatus::kInvalidInput, "no path to parameterise");
  const double length = path->length();
  if (std::optional<std::string> reason = invalidInput(length, b_start, drives)) {
    return fail(PlanStatus::kInvalidInput, std::move(*reason));
  }
  if (length == 0.0) {
    if (b_start > 0.0) {
      return fail(PlanStatus::kInfeasibleStart, "a moving start cannot be brought to rest on a zero-length path");
    }
    report.grid_points = 1;
    return Trajectory::create(std::move(path), drives, {0.0}, {0.0});
  }

  const double length_squared = length * length;
  const Move move{std::move(path), drives, length, length_squared, b_start, b_start / length_squared};
  problem_.b_start = move.unit_b_start;
  problem_.b_end = 0.0;
  problem_.cost_scale = 1.0;
  problem_.speed_bound = topp::unitSpeedBound(length);
  if (auto rows = sampleTimedRows(move, initialGridPoints(settings_), report); !rows) {
    return fail(PlanStatus::kInvalidInput, rows.error().message);
  }

  // Attempts until one passes the continuous check (algorithm.md section 3, "Stopping rules").
  const topp::AlSettings& al = settings_.solver;
  RowLimits rows = RowLimits::kAsGiven;
  for (int refinement = 0;; ++refinement) {
    Attempt attempt = solveRows(move, al, refinement == 0, report);
    const bool may_refine = refinement < settings_.max_limit_refinements;
    switch (attempt.end) {
      case Attempt::End::kWithinLimits:
      case Attempt::End::kBroken: return std::move(attempt.result);
      case Attempt::End::kHard: {
        // Tightened rows that turned out infeasible or hard are given up for a finer grid.
        if (rows != RowLimits::kTightened || !may_refine) return std::move(attempt.result);
        const Result<GridChange> change = refineGrid(move, report);
        if (!change) return fail(PlanStatus::kInvalidInput, change.error().message);
        if (change.value() == GridChange::kFinest) return std::move(attempt.result);
        rows = RowLimits::kAsGiven;
        ++report.refinements;
        break;
      }
      case Attempt::End::kOverLimits: {
        if (!may_refine) return fail(PlanStatus::kSolverNotConverged, overLimitsText(refinement, report));
        ++report.refinements;
        const Result<RowLimits> next = refineOrTighten(move, report);
        if (!next) return next.error();
        rows = next.value();
        break;
      }
    }
  }
}

Result<Trajectory> parameterizeTimeOptimal(std::shared_ptr<const GeometricPath> path, const DriveModel& drives,
                                           const ToppSettings& settings, double b_start, ToppReport* report) {
  ToppSolver solver(settings);
  return solver.solve(std::move(path), drives, b_start, report);
}

}  // namespace cyber::planner

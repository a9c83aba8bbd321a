#include "motion/fastest_stop.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "math/weighted_norm.hpp"
#include "path/joined_path.hpp"
#include "path/path_clearance.hpp"
#include "timing/topp_problem.hpp"
#include "timing/topp_reachability.hpp"

namespace cyber::planner {
namespace {

constexpr double kNoStop = std::numeric_limits<double>::infinity();
// False position keeps its point this share of the bracket inside either end, so that a bracket
// whose one end hardly moves still shrinks from the other (the Illinois halving's safeguard).
constexpr double kFalsePositionGuard = 0.01;

// Weighted distance from `start` along `direction` to the first joint limit.
double distanceToLimits(const RobotModel& model, const JointVector& start, const JointVector& direction) {
  double reach = kNoStop;
  for (int j = 0; j < model.jointCount(); ++j) {
    const JointRange range = model.range(j);
    if (direction[j] > 0.0) reach = std::min(reach, (range.max - start[j]) / direction[j]);
    if (direction[j] < 0.0) reach = std::min(reach, (range.min - start[j]) / direction[j]);
  }
  return std::max(0.0, reach);
}

// Where braking as hard as the rows at each node allow brings b_start to rest on a line of
// `length` (an outer bound on the admissible deceleration, so an estimate from below).
double stopDistanceEstimate(const StraightPath& line, const DriveModel& drives, double b_start, int points,
                            topp::Problem& problem, topp::LimitMargins& margins) {
  const double length = line.length();
  topp::sampleGrid(line, points, problem);
  margins.reset(problem.intervals());
  if (!topp::buildRows(drives, margins, problem)) return kNoStop;
  double b = b_start / (length * length);
  for (int k = 0; k < problem.intervals(); ++k) {
    const topp::AccelInterval a = topp::admissibleAcceleration(problem, k, b);
    if (a.empty() || a.lo >= 0.0) return kNoStop;
    const double next = b + 2.0 * a.lo * problem.ds(k);
    if (next <= 0.0) return (problem.s[static_cast<size_t>(k)] + b / (-2.0 * a.lo)) * length;
    b = next;
  }
  return kNoStop;
}

// The shortest stop's time-optimal profile is its reachability profile (it brakes from the first
// instant, so there is nothing for the optimiser to gain): rows at both ends and the middle of
// every interval, checked at the solver's step like the optimiser's result. kInfeasibleStart when
// b_start cannot be stopped on `line` as asked, kSolverNotConverged when the check fails.
Result<Trajectory> brakingProfile(const std::shared_ptr<const StraightPath>& line, const RobotModel& model,
                                  const DriveModel& drives, double b_start, int points, topp::Problem& problem,
                                  topp::LimitMargins& margins, std::vector<double>& profile,
                                  std::vector<double>& controllable) {
  using R = Result<Trajectory>;
  const double length = line->length();
  topp::sampleGrid(*line, points, problem);
  margins.reset(problem.intervals());
  if (auto rows = topp::buildRows(drives, margins, problem); !rows) return rows.error();
  problem.b_start = b_start / (length * length);
  problem.b_end = 0.0;
  problem.speed_bound = topp::unitSpeedBound(length);
  const topp::ReachabilityResult r = topp::forwardBackward(problem, profile, controllable);
  if (r.status != topp::ReachabilityStatus::kOk || r.start_b != problem.b_start) {
    return R::failure(PlanStatus::kInfeasibleStart, "the start speed cannot be braked to rest on this line");
  }
  R trajectory = topp::unitProfileTrajectory(
      line, drives, problem, [&](size_t k) { return profile[k]; }, length * length, b_start);
  if (!trajectory) return trajectory;
  if (!withinDriveLimits(trajectory.value(), model.planner.topp)) {
    return R::failure(PlanStatus::kSolverNotConverged, "the braking profile exceeds a limit between its rows");
  }
  return trajectory;
}

// Lines along `direction` from `start` being sized for the stop, and the buffers their profiles
// reuse: the length search below asks it about one length after another.
struct StopLines {
  const JointVector& start;
  const JointVector& direction;
  const DriveModel& drives;
  double b_start;
  int points;
  topp::Problem& problem;
  topp::LimitMargins& margins;
  std::vector<double>& profile;
  std::vector<double>& controllable;

  // How much more than b_start the line of `length` can still stop from, relative (negative: it
  // cannot stop b_start; -1 when no profile exists). Increasing in length.
  double margin(double length) const {
    if (length <= 0.0) return -1.0;
    topp::sampleGrid(StraightPath(start, direction, length), points, problem);
    margins.reset(problem.intervals());
    if (!topp::buildRows(drives, margins, problem)) return -1.0;
    problem.b_start = 0.0;
    problem.b_end = 0.0;
    problem.speed_bound = topp::unitSpeedBound(length);
    const topp::ReachabilityResult r = topp::forwardBackward(problem, profile, controllable);
    if (r.status != topp::ReachabilityStatus::kOk) return -1.0;
    return r.controllable_start_b * length * length / b_start - 1.0;
  }
};

// Lengths lo < hi whose margins m_lo < 0 <= m_hi enclose the shortest line that stops.
struct StopBracket {
  double lo;
  double hi;
  double m_lo;
  double m_hi;
};

// Widens a bracket around the estimate until it encloses the shortest stopping line; none when
// no line up to `reach` stops. Its own step, before the root finding, so each reads alone.
std::optional<StopBracket> bracketStop(const StopLines& lines, double reach, double estimate,
                                       const StopSettings& settings) {
  double hi = std::min(reach, estimate);
  double m_hi = lines.margin(hi);
  for (int i = 0; i < settings.bracket_steps && m_hi < 0.0; ++i) {
    if (hi >= reach) return std::nullopt;
    hi = std::min(reach, settings.bracket_growth * hi);
    m_hi = lines.margin(hi);
  }
  if (m_hi < 0.0) return std::nullopt;
  double lo = hi / settings.bracket_growth;
  double m_lo = lines.margin(lo);
  for (int i = 0; i < settings.bracket_steps && m_lo >= 0.0; ++i) {
    hi = lo, m_hi = m_lo;
    lo /= settings.bracket_growth;
    m_lo = lines.margin(lo);
  }
  return StopBracket{lo, hi, m_lo, m_hi};
}

// The shortest stopping length within length_tolerance, from above. The stoppable b grows about in
// proportion to the length (b = 2 a d), so the margin is nearly linear in it: false position with
// the Illinois halving converges in a few passes where bisection takes a dozen; bisection where
// the lower end has no profile.
double shortestStopLength(const StopLines& lines, StopBracket bracket, double length_tolerance) {
  double lo = bracket.lo, hi = bracket.hi, m_lo = bracket.m_lo, m_hi = bracket.m_hi;
  double f_lo = m_lo, f_hi = m_hi;  // the interpolated values, halved on the side that stays
  int kept_side = 0;
  while (hi - lo > length_tolerance * hi && m_hi > length_tolerance) {
    double mid = 0.5 * (lo + hi);
    if (m_lo > -1.0)
      mid = std::clamp(hi - f_hi * (hi - lo) / (f_hi - f_lo), lo + kFalsePositionGuard * (hi - lo),
                       hi - kFalsePositionGuard * (hi - lo));
    const double m_mid = lines.margin(mid);
    if (m_mid >= 0.0) {
      hi = mid, m_hi = f_hi = m_mid;
      if (kept_side == -1) f_lo *= 0.5;
      kept_side = -1;
    } else {
      lo = mid, m_lo = f_lo = m_mid;
      if (kept_side == 1) f_hi *= 0.5;
      kept_side = 1;
    }
  }
  return hi;
}

}  // namespace

Result<Trajectory> fastestStop(const RobotModel& model, const CollisionWorld& world, const JointVector& start,
                               const JointVector& velocity, ToppSolver& solver) {
  using R = Result<Trajectory>;
  const StopSettings& settings = model.planner.stop;
  const double speed = weightedNorm(velocity, model.planner.metric);
  if (!std::isfinite(speed) || speed <= 0.0) return R::failure(PlanStatus::kInvalidInput, "no velocity to stop from");
  const JointVector direction = velocity / speed;
  const double b_start = speed * speed;
  const DriveModel drives = model.driveModel(world.pieces());
  const double reach = std::min(distanceToLimits(model, start, direction), settings.max_length);
  const auto cannot_stop = [] {
    return R::failure(PlanStatus::kInfeasibleStart,
                      "the start velocity cannot be braked to rest inside the joint limits");
  };
  if (reach <= 0.0) return cannot_stop();

  topp::Problem problem;
  topp::LimitMargins margins;
  const double estimate = stopDistanceEstimate(StraightPath(start, direction, reach), drives, b_start,
                                               settings.estimate_points, problem, margins);
  if (estimate == kNoStop) return cannot_stop();
  // The shortest line whose controllable start (on the solver's own grid) holds b_start: on it the
  // time-optimal profile brakes from the first instant (a longer one would first speed up).
  const int points = std::max(3, solver.settings().grid_points);
  std::vector<double> profile, controllable;
  const StopLines lines{start, direction, drives, b_start, points, problem, margins, profile, controllable};
  const std::optional<StopBracket> bracket = bracketStop(lines, reach, estimate, settings);
  if (!bracket) return cannot_stop();

  double length = shortestStopLength(lines, *bracket, settings.length_tolerance);
  for (int attempt = 0; attempt <= settings.max_retries;
       ++attempt, length = std::min(reach, settings.retry_growth * length)) {
    auto line = std::make_shared<const StraightPath>(start, direction, length);
    R braking = brakingProfile(line, model, drives, b_start, points, problem, margins, profile, controllable);
    // The optimiser's refined limits when the profile's own check fails (docs/moving-starts.md).
    if (!braking.ok() && braking.status() == PlanStatus::kSolverNotConverged) {
      ToppReport report;
      braking = solver.solve(line, drives, b_start, &report);
      // A start clamped into the controllable set would not begin at v0: lengthen instead.
      if (braking.ok() && report.start_speed_ratio != 1.0) braking = cannot_stop();
    }
    if (braking.ok()) {
      if (!checkSegment(world, start, line->at(length).q, model.clearance_m).clear) {
        return R::failure(PlanStatus::kClearanceNotMet,
                          "braking along the start velocity comes closer than the clearance");
      }
      return braking;
    }
    if (braking.status() != PlanStatus::kInfeasibleStart) return braking;
    if (length >= reach) break;
  }
  return cannot_stop();
}

}  // namespace cyber::planner

namespace cyber::planner {

Result<Trajectory> stretchedStop(const RobotModel& model, const CollisionWorld& world, const Trajectory& stop,
                                 double factor) {
  using R = Result<Trajectory>;
  const PathPoint start = stop.path().at(0.0);
  const double length = factor * stop.path().length();
  auto line = std::make_shared<const StraightPath>(start.q, start.dq_ds, length);
  const JointVector end = line->at(length).q;
  if (!model.withinLimits(end))
    return R::failure(PlanStatus::kInfeasibleStart, "a gentler stop leaves the joint range");
  if (!checkSegment(world, start.q, end, model.clearance_m).clear) {
    return R::failure(PlanStatus::kClearanceNotMet, "a gentler stop comes closer than the clearance");
  }
  std::vector<double> s_grid = stop.sGrid();
  for (double& s : s_grid) s *= factor;
  s_grid.back() = length;
  return Trajectory::create(std::move(line), stop.drives(), std::move(s_grid), stop.bGrid());
}

}  // namespace cyber::planner

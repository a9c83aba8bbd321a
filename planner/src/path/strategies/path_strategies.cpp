#include "path/strategies/path_strategies.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "math/weighted_norm.hpp"
#include "path/joined_path.hpp"
#include "path/path_optimizer.hpp"
#include "path/path_shaping.hpp"
#include "timing/path_timing.hpp"

namespace cyber::planner {
namespace {

double estimateOf(const CandidateInputs& in, const PlannedPath& candidate, int grid_points) {
  return estimateDuration(*candidate.path, in.drives, in.b_start, grid_points);
}

// The strategies the test programs register at static initialisation (PathStrategyRegistration).
std::vector<PathStrategy>& registeredStrategies() {
  static std::vector<PathStrategy> registered;
  return registered;
}

}  // namespace

void putFirstIfFaster(const CandidateInputs& in, CandidateList& list, const PlannedPath& fastest, double fastest_s,
                      CubicSplinePath path, std::vector<JointVector> waypoints, double min_clearance_m,
                      PlanMethod::Smoothing smoothing) {
  const PathStrategySettings& s = in.settings();
  if (!(estimateDuration(path, in.drives, in.b_start, s.check_grid_points) < (1.0 - s.shape_gain) * fastest_s)) return;
  PlannedPath better = fastest;
  better.path = std::make_shared<const CubicSplinePath>(std::move(path));
  better.waypoints = std::move(waypoints);
  better.min_clearance_m = min_clearance_m;
  better.method.shaped_from = smoothing == PlanMethod::Smoothing::kShaped ? fastest.method.strategy : "";
  better.method.smoothing = smoothing;
  list.putFirst(std::move(better));
}

void addShaped(const CandidateInputs& in, CandidateList& list, const PlannedPath& fastest,
               const std::vector<JointVector>& knots) {
  const PlannerSettings& settings = in.model.planner;
  ShapedPath shaped =
      shapeForTime(knots, in.fixed_head, in.start_velocity, in.world, in.model, in.b_start, settings.shape_search);
  const ShapeRefinementSettings& refinement = settings.shape_refinement;
  if (shaped.estimate_s >
      settings.strategies.refine_ratio *
          slowerJointAlone(in.from(), in.goal, in.drives, settings.metric, refinement.grid_points)) {
    ShapedPath refined = refineShapeForTime(shaped.waypoints, in.fixed_head, in.start_velocity, in.world, in.model,
                                            in.b_start, refinement);
    if (refined.improvements > 0) {
      refined.improvements += shaped.improvements;
      shaped = std::move(refined);
    }
  }
  if (shaped.improvements == 0) return;
  putFirstIfFaster(in, list, fastest, estimateOf(in, fastest, settings.strategies.check_grid_points),
                   std::move(shaped.path), std::move(shaped.waypoints), shaped.min_clearance_m,
                   PlanMethod::Smoothing::kShaped);
}

// From each kept point the farthest reachable node is found by bisection: clear segments are
// nearly monotone along a search path.
std::vector<JointVector> shortcutPolyline(const CollisionWorld& world, const std::vector<JointVector>& polyline,
                                          int fixed_head, double clearance_m) {
  std::vector<JointVector> out(polyline.begin(), polyline.begin() + fixed_head);
  const int last = static_cast<int>(polyline.size()) - 1;
  int from = fixed_head - 1;
  while (from < last) {
    int lo = from + 1, hi = last;
    auto clear = [&](int to) {
      return checkSegment(world, polyline[static_cast<size_t>(from)], polyline[static_cast<size_t>(to)], clearance_m)
          .clear;
    };
    if (clear(hi)) {
      lo = hi;
    } else {
      while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        (clear(mid) ? lo : hi) = mid;
      }
    }
    out.push_back(polyline[static_cast<size_t>(lo)]);
    from = lo;
  }
  return out;
}

double shortcutClearance(const CandidateInputs& in) {
  return in.model.clearance_m * (1.0 + in.settings().shortcut_margin_clearances);
}

void addSmoothed(const CandidateInputs& in, CandidateList& list, const std::vector<JointVector>& line) {
  PlannedPath alternative = in.first;
  if (smoothPolyline(in, line, alternative, list)) list.addInTimeOrder(in, std::move(alternative));
}

double CandidateList::estimate(const CandidateInputs& in, size_t i) {
  if (std::isnan(estimates_s_[i])) estimates_s_[i] = estimateOf(in, paths_[i], in.settings().timing_grid_points);
  return estimates_s_[i];
}

void CandidateList::addInTimeOrder(const CandidateInputs& in, PlannedPath path) {
  path.method.strategy = adding_for;
  const double seconds = estimateOf(in, path, in.settings().timing_grid_points);
  size_t at = 0;
  while (at < paths_.size() && estimate(in, at) <= seconds) ++at;
  estimates_s_.insert(estimates_s_.begin() + static_cast<long>(at), seconds);
  paths_.insert(paths_.begin() + static_cast<long>(at), std::move(path));
}

void CandidateList::putFirst(PlannedPath path) {
  path.method.strategy = adding_for;
  estimates_s_.insert(estimates_s_.begin(), std::numeric_limits<double>::quiet_NaN());
  paths_.insert(paths_.begin(), std::move(path));
}

bool smoothPolyline(const CandidateInputs& in, const std::vector<JointVector>& line, PlannedPath& into,
                    CandidateList& list) {
  using Smoothing = PlanMethod::Smoothing;
  const JointVector& metric = in.model.planner.metric;
  const SmoothingSettings& smoothing = in.model.planner.smoothing;
  const int fixed_head = in.fixed_head;
  const std::vector<JointVector> tail(line.begin() + fixed_head - 1, line.end());
  auto prior_at = [&](double spacing) {
    std::vector<JointVector> prior(line.begin(), line.begin() + fixed_head - 1);
    const std::vector<JointVector> resampled = resamplePolyline(tail, metric, spacing);
    prior.insert(prior.end(), resampled.begin(), resampled.end());
    return prior;
  };
  auto accept = [&](const std::vector<JointVector>& waypoints, Smoothing how) {
    auto spline = CubicSplinePath::through(waypoints, metric, in.start_velocity);
    if (!spline.ok()) return false;
    list.last_check = checkPath(spline.value(), in.world, in.model, in.model.clearance_m);
    if (!list.last_check.ok()) return false;
    into.path = std::make_shared<const CubicSplinePath>(std::move(spline).value());
    into.waypoints = waypoints;
    into.min_clearance_m = list.last_check.min_distance_m;
    into.method.smoothing = how;
    return true;
  };
  if (in.direct && fixed_head == 1) return accept(line, Smoothing::kStraight);
  const std::vector<JointVector> prior = prior_at(smoothing.waypoint_spacing);
  const SmoothingResult optimised = optimizePath(in.world, prior, fixed_head, in.model, smoothing);
  into.optimizer_iterations += optimised.lbfgs.iterations;
  if (accept(optimised.waypoints, Smoothing::kOptimised)) return true;
  SmoothingSettings stronger = smoothing;
  stronger.obstacle_weight *= smoothing.retry_obstacle_factor;
  const SmoothingResult pushed = optimizePath(in.world, prior, fixed_head, in.model, stronger);
  into.optimizer_iterations += pushed.lbfgs.iterations;
  if (accept(pushed.waypoints, Smoothing::kStrongerObstacleWeight)) return true;
  if (accept(prior, Smoothing::kPrior)) return true;
  return accept(prior_at(smoothing.dense_prior_share * smoothing.waypoint_spacing), Smoothing::kDensePrior);
}

double straightEstimate(const JointVector& from, const JointVector& to, const DriveModel& drives,
                        const JointVector& metric, int grid_points) {
  const double length = weightedNorm(to - from, metric);
  if (!(length > kSamePoseWeighted)) return 0.0;
  return estimateDuration(StraightPath(from, (to - from) / length, length), drives, 0.0, grid_points);
}

double slowerJointAlone(const JointVector& from, const JointVector& to, const DriveModel& drives,
                        const JointVector& metric, int grid_points) {
  double slower = 0.0;
  for (int joint = 0; joint < from.size(); ++joint) {
    JointVector alone = from;
    alone[joint] = to[joint];
    slower = std::max(slower, straightEstimate(from, alone, drives, metric, grid_points));
  }
  return slower;
}

std::span<const PathStrategy> pathStrategies() {
  // Every file of path/strategies/ but this one is a strategy; the build lists them
  // (planner/CMakeLists.txt), and the order each names decides when it is tried.
  static const std::vector<PathStrategy> ordered = [] {
    std::vector<PathStrategy> all;
    for (const PathStrategy* strategy : builtInPathStrategies()) all.push_back(*strategy);
    const std::vector<PathStrategy>& registered = registeredStrategies();
    all.insert(all.end(), registered.begin(), registered.end());
    std::stable_sort(all.begin(), all.end(),
                     [](const PathStrategy& a, const PathStrategy& b) { return a.order < b.order; });
    return all;
  }();
  return ordered;
}

PathStrategyRegistration::PathStrategyRegistration(const PathStrategy& strategy) {
  registeredStrategies().push_back(strategy);
}

}  // namespace cyber::planner

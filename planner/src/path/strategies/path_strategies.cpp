#include "path/strategies/path_strategies.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>

#include "math/weighted_norm.hpp"
#include "path/joined_path.hpp"
#include "path/path_optimizer.hpp"
#include "path/path_shaping.hpp"
#include "path/synchronised_path.hpp"
#include "timing/path_timing.hpp"

namespace cyber::planner {
namespace {

double estimateOf(const CandidateInputs& in, const PlannedPath& candidate, int grid_points) {
  return estimateDuration(*candidate.path, in.drives, in.b_start, grid_points);
}

// `path` through `waypoints` put first, in `fastest`'s place, when an estimate on a finer grid than
// the searches' own confirms it faster (a coarse estimate can be fooled between its points).
// fastest_s: `fastest`'s estimate on that grid.
void putFirstIfFaster(const CandidateInputs& in, CandidateList& list, const PlannedPath& fastest, double fastest_s,
                      CubicSplinePath path, std::vector<JointVector> waypoints, double min_clearance_m,
                      std::string method) {
  const PathStrategySettings& s = in.settings();
  if (!(estimateDuration(path, in.drives, in.b_start, s.check_grid_points) < (1.0 - s.shape_gain) * fastest_s)) return;
  PlannedPath better = fastest;
  better.path = std::make_shared<const CubicSplinePath>(std::move(path));
  better.waypoints = std::move(waypoints);
  better.min_clearance_m = min_clearance_m;
  better.method = std::move(method);
  list.putFirst(std::move(better));
}

// The shape search from `knots` (through which `fastest` runs), refined further when its shape
// is still estimated well above the slower joint moving alone.
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
                   "shaped for time, " + fastest.method);
}

// The search's polyline with every run of nodes that a straight segment (clear by `clearance_m`)
// can replace replaced by it. The first fixed_head points are kept. From each kept point the
// farthest reachable node is found by bisection (clear segments are nearly monotone along a
// search path).
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

// Every node within `radius` index steps of the path's cells, except those within `radius` of
// its two ends (the search must still leave the start and reach the goal): blocking this band
// makes the search find the way round the other side of an obstacle, when there is one.
std::vector<std::uint8_t> bandAround(const CSpaceGrid& grid, const std::vector<int>& cells, int radius) {
  std::vector<std::uint8_t> band(static_cast<size_t>(grid.cellCount()), 0);
  if (cells.empty()) return band;
  const int ni = grid.firstAxis().count, nj = grid.secondAxis().count;
  auto near_end = [&](int i, int j) {
    for (int end : {cells.front(), cells.back()}) {
      if (std::abs(i - grid.firstIndex(end)) <= radius && std::abs(j - grid.secondIndex(end)) <= radius) return true;
    }
    return false;
  };
  for (int cell : cells) {
    const int i0 = grid.firstIndex(cell), j0 = grid.secondIndex(cell);
    for (int i = std::max(0, i0 - radius); i <= std::min(ni - 1, i0 + radius); ++i) {
      for (int j = std::max(0, j0 - radius); j <= std::min(nj - 1, j0 + radius); ++j) {
        if (!near_end(i, j)) band[static_cast<size_t>(grid.cell(i, j))] = 1;
      }
    }
  }
  return band;
}

// `line` smoothed as a copy of the first path, added in the order of estimated time.
void addSmoothed(const CandidateInputs& in, CandidateList& list, const std::vector<JointVector>& line,
                 const char* label) {
  PlannedPath alternative = in.first;
  if (smoothPolyline(in, line, label, alternative, list)) list.addInTimeOrder(in, std::move(alternative));
}

constexpr std::array kStrategies{
    PathStrategy{"shape the straight segment",
                 "a straight segment is not the fastest path when the joints' limits differ (gravity, voltage)",
                 shapeStraightSegment},
    PathStrategy{"shortcut", "the search's grid and potential bend the path; time favours straight segments",
                 shortcutSearchPath},
    PathStrategy{"other ways round", "the search finds one way round an obstacle; another may be faster",
                 searchOtherWays},
    PathStrategy{"shape the fastest path", "the fastest path keeps to the middle of the free space; time may not",
                 shapeFastestPath},
    PathStrategy{"synchronise the joints",
                 "from rest, many moves are as fast as their slower joint alone; the search's paths lose 3-5 %",
                 synchroniseJoints},
};

}  // namespace

double CandidateList::estimate(const CandidateInputs& in, size_t i) {
  if (std::isnan(estimates_s_[i])) estimates_s_[i] = estimateOf(in, paths_[i], in.settings().timing_grid_points);
  return estimates_s_[i];
}

void CandidateList::addInTimeOrder(const CandidateInputs& in, PlannedPath path) {
  const double seconds = estimateOf(in, path, in.settings().timing_grid_points);
  size_t at = 0;
  while (at < paths_.size() && estimate(in, at) <= seconds) ++at;
  estimates_s_.insert(estimates_s_.begin() + static_cast<long>(at), seconds);
  paths_.insert(paths_.begin() + static_cast<long>(at), std::move(path));
}

void CandidateList::putFirst(PlannedPath path) {
  estimates_s_.insert(estimates_s_.begin(), std::numeric_limits<double>::quiet_NaN());
  paths_.insert(paths_.begin(), std::move(path));
}

bool smoothPolyline(const CandidateInputs& in, const std::vector<JointVector>& line, const std::string& label,
                    PlannedPath& into, CandidateList& list) {
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
  auto accept = [&](const std::vector<JointVector>& waypoints, const std::string& method) {
    auto spline = CubicSplinePath::through(waypoints, metric, in.start_velocity);
    if (!spline.ok()) return false;
    list.last_check = checkPath(spline.value(), in.world, in.model, in.model.clearance_m);
    if (!list.last_check.ok()) return false;
    into.path = std::make_shared<const CubicSplinePath>(std::move(spline).value());
    into.waypoints = waypoints;
    into.min_clearance_m = list.last_check.min_distance_m;
    into.method = label + method;
    return true;
  };
  if (in.direct && fixed_head == 1) return accept(line, "straight");
  const std::vector<JointVector> prior = prior_at(smoothing.waypoint_spacing);
  const SmoothingResult optimised = optimizePath(in.world, prior, fixed_head, in.model, smoothing);
  into.optimizer_iterations += optimised.lbfgs.iterations;
  if (accept(optimised.waypoints, "optimised")) return true;
  SmoothingSettings stronger = smoothing;
  stronger.obstacle_weight *= 10.0;
  const SmoothingResult pushed = optimizePath(in.world, prior, fixed_head, in.model, stronger);
  into.optimizer_iterations += pushed.lbfgs.iterations;
  if (accept(pushed.waypoints, "optimised, obstacle weight x10")) return true;
  if (accept(prior, "prior")) return true;
  return accept(prior_at(0.25 * smoothing.waypoint_spacing), "dense prior");
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
  for (int joint = 0; joint < kJointCount; ++joint) {
    JointVector alone = from;
    alone[joint] = to[joint];
    slower = std::max(slower, straightEstimate(from, alone, drives, metric, grid_points));
  }
  return slower;
}

std::span<const PathStrategy> pathStrategies() { return kStrategies; }

// A direct path, bent by the shape search from knots spread evenly along it; only when the
// segment is estimated slower than its slower joint moving alone (otherwise that joint's limits
// bind all along and no shape can be faster).
void shapeStraightSegment(const CandidateInputs& in, CandidateList& list) {
  if (!in.direct || list.empty()) return;
  const PathStrategySettings& s = in.settings();
  const JointVector& metric = in.model.planner.metric;
  if (!(straightEstimate(in.from(), in.goal, in.drives, metric, s.gate_grid_points) >
        s.direct_shape_ratio * slowerJointAlone(in.from(), in.goal, in.drives, metric, s.gate_grid_points))) {
    return;
  }
  const std::vector<JointVector> tail(in.polyline.begin() + in.fixed_head - 1, in.polyline.end());
  std::vector<JointVector> knots(in.polyline.begin(), in.polyline.begin() + in.fixed_head - 1);
  const double tail_length = weightedNorm(tail.back() - tail.front(), metric);
  const std::vector<JointVector> spread = resamplePolyline(tail, metric, tail_length / (s.direct_shape_knots - 1));
  knots.insert(knots.end(), spread.begin(), spread.end());
  const PlannedPath straight = list.front();
  addShaped(in, list, straight, knots);
}

// The search's polyline with every run of nodes that one clear straight segment can replace
// replaced by it (docs/performance.md, "Choosing the path for time").
void shortcutSearchPath(const CandidateInputs& in, CandidateList& list) {
  if (in.direct) return;
  const std::vector<JointVector> shortcut =
      shortcutPolyline(in.world, in.polyline, in.fixed_head, shortcutClearance(in));
  if (shortcut.size() < in.polyline.size()) addSmoothed(in, list, shortcut, "shortcut, ");
}

// When the fastest path is a detour (estimated well above the straight segment): the search again
// with the first path's band blocked or, where C-space has holes, on the other side of each.
void searchOtherWays(const CandidateInputs& in, CandidateList& list) {
  if (in.direct || list.empty()) return;
  const PathStrategySettings& s = in.settings();
  if (!(list.estimate(in, 0) > s.detour_ratio * in.straight_estimate_s)) return;
  auto add_search = [&](const std::optional<SearchPath>& found, const char* label) {
    if (!found) return;
    std::vector<JointVector> around(in.polyline.begin(), in.polyline.begin() + in.fixed_head);
    for (int cell : found->cells) around.push_back(in.grid.node(cell));
    around.push_back(in.goal);
    addSmoothed(in, list, shortcutPolyline(in.world, around, in.fixed_head, shortcutClearance(in)), label);
  };
  // Without a hole the other way round is the search with the first path's band blocked; with
  // holes, the other side of each (the band also blocks a narrow corridor both ways share, leaving
  // a low pose with a piece held for example, and finds nothing).
  const std::vector<GridHole>& holes = in.grid.holes();
  if (holes.empty()) {
    const std::vector<std::uint8_t> band = bandAround(in.grid, in.first_cells, s.band_radius_nodes);
    add_search(astarSearch(in.grid, in.source_links, in.goal_links, in.goal, SearchOptions{.also_blocked = band}),
               "other way round, ");
  }
  for (size_t h = 0; h < std::min(holes.size(), static_cast<size_t>(s.max_hole_sides)); ++h) {
    const SideOfHole other_side{holes[h], 1 - rayCrossingParity(in.grid, holes[h], in.first_cells)};
    add_search(astarSearch(in.grid, in.source_links, in.goal_links, in.goal,
                           SearchOptions{.side = other_side, .max_cost = s.max_side_cost * in.first_cost}),
               "other side, ");
  }
}

// The fastest searched candidate's shape searched against its estimated time, when it is
// estimated well above the straight segment.
void shapeFastestPath(const CandidateInputs& in, CandidateList& list) {
  if (in.direct || list.empty()) return;
  if (!(list.estimate(in, 0) > in.settings().shape_ratio * in.straight_estimate_s)) return;
  const PlannedPath fastest = list.front();
  addShaped(in, list, fastest, fastest.waypoints);
}

// From rest, the joints' own fastest motions side by side (synchronised_path.hpp), inside a window
// of the fastest candidate's estimate over the slower joint alone. That coarser estimate first:
// the joints' own profiles cost five times as much, and half the public moves are already within
// a per cent of it.
void synchroniseJoints(const CandidateInputs& in, CandidateList& list) {
  if (list.empty() || !(in.start_velocity.array() == 0.0).all()) return;
  const PathStrategySettings& s = in.settings();
  const PlannedPath fastest = list.front();
  const double fastest_s = estimateDuration(*fastest.path, in.drives, 0.0, s.check_grid_points);
  const double slower_alone_s =
      slowerJointAlone(in.start, in.goal, in.drives, in.model.planner.metric, s.timing_grid_points);
  if (!(fastest_s > s.synchronised_ratio * slower_alone_s && fastest_s < s.synchronised_max_ratio * slower_alone_s)) {
    return;
  }
  if (auto synchronised = synchronisedPath(in.start, in.goal, in.world, in.model, fastest_s / s.synchronised_ratio,
                                           in.model.planner.synchronised)) {
    putFirstIfFaster(in, list, fastest, fastest_s, std::move(synchronised->path), std::move(synchronised->waypoints),
                     synchronised->min_clearance_m, "synchronised joints");
  }
}

}  // namespace cyber::planner

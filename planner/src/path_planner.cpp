#include "cyber/planner/path_planner.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "cyber/planner/astar_search.hpp"
#include "cyber/planner/joined_path.hpp"
#include "cyber/planner/path_clearance.hpp"
#include "cyber/planner/path_optimizer.hpp"
#include "cyber/planner/path_shaping.hpp"
#include "cyber/planner/path_timing.hpp"
#include "cyber/planner/synchronised_path.hpp"
#include "cyber/planner/weighted_norm.hpp"

namespace cyber::planner {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

std::string poseText(const RobotModel& model, const JointVector& q) {
  return fmt::format("({:.4f} {}, {:.4f} {})", q[0], unitName(model.joints[0].type), q[1],
                     unitName(model.joints[1].type));
}

std::string rangeText(const RobotModel& model) {
  return fmt::format("{} [{:.4f}, {:.4f}], {} [{:.4f}, {:.4f}]", model.joints[0].name, model.range(0).min,
                     model.range(0).max, model.joints[1].name, model.range(1).min, model.range(1).max);
}

std::string obstacleName(const Scene& scene, int index) {
  // CollisionWorld numbers the field elements, then the fixed obstacles, and skips empty
  // polygons; the loader never produces them, so indices agree.
  const int movable = static_cast<int>(scene.obstacles.size());
  if (index >= 0 && index < movable) return scene.obstacles[static_cast<size_t>(index)].name;
  if (index >= movable && index - movable < static_cast<int>(scene.fixed.size())) {
    return scene.fixed[static_cast<size_t>(index - movable)].name;
  }
  return "an obstacle";
}

constexpr double kSamePose = 1e-9;     // weighted; closer poses are the same pose
constexpr int kMaxConnectionRing = 4;  // nodes up to this many steps from a pose may be connected
constexpr int kLeadInHalvings = 5;

// Free grid nodes near a pose that a straight, clear segment reaches, with the connection cost
// |segment|_Sigma (1 + w p(node) / 2) >= |segment|_Sigma (what A*'s heuristic needs). Tries the
// 2 x 2 nodes around the pose first and widens ring by ring.
std::vector<SearchEndpoint> connectToGrid(const CSpaceGrid& grid, const CollisionWorld& world, const JointVector& pose,
                                          double clearance_m) {
  std::vector<SearchEndpoint> out;
  const int corner = grid.lowerCorner(pose);
  const int i0 = grid.firstIndex(corner), j0 = grid.secondIndex(corner);
  for (int ring = 1; ring <= kMaxConnectionRing && out.empty(); ++ring) {
    for (int i = i0 - ring + 1; i <= i0 + ring; ++i) {
      for (int j = j0 - ring + 1; j <= j0 + ring; ++j) {
        if (i < 0 || j < 0 || i >= grid.firstAxis().count || j >= grid.secondAxis().count) continue;
        // Only the new ring: the inner nodes were tried already.
        const bool inner = i > i0 - ring + 1 && i < i0 + ring && j > j0 - ring + 1 && j < j0 + ring;
        if (ring > 1 && inner) continue;
        const int cell = grid.cell(i, j);
        if (grid.blocked(cell)) continue;
        if (!checkSegment(world, pose, grid.node(cell), clearance_m).clear) continue;
        const double length = weightedNorm(grid.node(cell) - pose, grid.metric());
        out.push_back({cell, length * (1.0 + 0.5 * grid.potentialWeight() * grid.potential(cell))});
      }
    }
  }
  return out;
}

// Candidate paths are timed by the reachability pass on this many grid points (path_timing.hpp).
constexpr int kTimingGridPoints = 60;
// Shortcut segments keep this much more than the clearance, so smoothing has room at corners.
constexpr double kShortcutMargin_m = 0.015;
// The other way round is searched for when the best path takes this much longer than the straight
// segment would (obstacles ignored), with the first path's band this many nodes wide blocked.
constexpr double kDetourRatio = 1.05;
constexpr int kBandRadius = 6;
// The fastest candidate's shape is searched against its estimated time when it is estimated this
// much slower than the straight segment, and kept when a finer estimate (grid points) finds it this
// much faster: the search's own coarse estimate could be fooled between its grid points.
constexpr double kShapeRatio = 1.02;
constexpr double kShapeGain = 0.002;
constexpr int kShapeCheckGridPoints = 100;
// The shape search goes on with more bumps and evaluations (path_shaping.hpp) when its shape is
// still estimated this much slower than the slower joint alone (40 grid points each). On the
// public moves 53 pass (50 are refined: three are direct paths with too few knots); at 1.10 two
// moves (one with a piece held, one without) stayed above 1.03 of the best known.
constexpr double kRefineRatio = 1.05;
// A direct path is shaped from this many knots along its straight segment, when its estimate (on
// this many grid points) is this much above its slower joint's alone: on the public moves those
// that gained were 1.006-1.06 above, the others equal (one joint's limits bind all along).
constexpr int kDirectShapeKnots = 6;
constexpr int kGateGridPoints = 20;
constexpr double kDirectShapeRatio = 1.003;
// The synchronised candidate is tried when the slower joint alone is this much faster than the
// fastest candidate's estimate (100 grid points): below that it cannot gain enough to matter.
constexpr double kSynchronisedRatio = 1.01;
// Nor when it is this much slower: then the obstacles decide the move, and the joints' own motions
// side by side run into them (on the public moves the synchronised candidate was found only below
// 1.045; above, its profiles and clearance checks cost 1-2 ms for nothing).
constexpr double kSynchronisedMaxRatio = 1.08;
// The other side of this many holes of C-space (the largest) is searched for as well.
// Only when it costs at most this much more than the first path in the search's own metric (the
// other sides that were faster on the public moves cost 1.03-1.06 times as much; most that were
// not, 1.1 to 4.5 times): the search gives up early on a far detour, and it is not smoothed.
constexpr size_t kMaxHoleSides = 2;
constexpr double kMaxSideCost = 1.08;

// The reachability estimate from rest of the straight segment from `from` to `to` (obstacles
// ignored); 0 when they are the same pose.
double straightEstimate(const JointVector& from, const JointVector& to, const JointVector& metric,
                        const DriveModel& drives, int grid_points = kTimingGridPoints) {
  const double length = weightedNorm(to - from, metric);
  if (!(length > kSamePose)) return 0.0;
  return estimateDuration(StraightPath(from, (to - from) / length, length), drives, 0.0, grid_points);
}

// The larger of the joints' straightEstimate moving alone (the other one staying at `from`).
double slowerJointAlone(const JointVector& from, const JointVector& to, const JointVector& metric,
                        const DriveModel& drives, int grid_points = kGateGridPoints) {
  double slower = 0.0;
  for (int joint = 0; joint < kJointCount; ++joint) {
    JointVector alone = from;
    alone[joint] = to[joint];
    slower = std::max(slower, straightEstimate(from, alone, metric, drives, grid_points));
  }
  return slower;
}

// The search's polyline with every run of nodes that a straight segment (clear by `clearance_m`)
// can replace replaced by it: the search's grid and potential bend the path toward the middle of
// the free space, while time favours moving both joints at once in straight lines. The first
// fixed_head points are kept. From each kept point the farthest reachable node is found by
// bisection (clear segments are nearly monotone along a search path).
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

}  // namespace

PathPlanner::PathPlanner(const RobotModel& model, const Scene& scene, const JointRange& band)
    : model_(model), scene_(scene), band_(band) {
  const int sets = model_.pieceSetCount();
  auto grids = std::make_shared<Grids>();
  worlds_.reserve(static_cast<size_t>(sets));
  grids->grids.reserve(static_cast<size_t>(sets));
  grids->build_ms.assign(static_cast<size_t>(sets), 0.0);
  const double centre = 0.5 * (band.min + band.max);
  for (int set = 0; set < sets; ++set) {
    const Clock::time_point t0 = Clock::now();
    const HeldPieces pieces = HeldPieces::fromIndex(set);
    // A band wider than one offset searches the world swept over it; its checks use one offset.
    if (band.max > band.min) {
      grids->grids.push_back(CSpaceGrid::build(CollisionWorld(model_, scene_, pieces, band), model_));
      worlds_.emplace_back(model_, scene_, pieces, centre);
    } else {
      worlds_.emplace_back(model_, scene_, pieces, centre);
      grids->grids.push_back(CSpaceGrid::build(worlds_.back(), model_));
    }
    grids->build_ms[static_cast<size_t>(set)] = millisecondsSince(t0);
  }
  grids_ = std::move(grids);
}

PathPlanner PathPlanner::atOffset(double scene_offset_m) const {
  PathPlanner out(*this);
  out.worlds_.clear();
  for (int set = 0; set < model_.pieceSetCount(); ++set) {
    out.worlds_.emplace_back(model_, scene_, HeldPieces::fromIndex(set), scene_offset_m);
  }
  return out;
}

Result<std::vector<PlannedPath>> PathPlanner::candidates(const JointVector& start, const JointVector& goal,
                                                         HeldPieces pieces, const JointVector& start_velocity,
                                                         PathAlternatives alternatives) const {
  using R = Result<std::vector<PlannedPath>>;
  if (!start.allFinite()) return R::failure(PlanStatus::kInvalidInput, "start pose is not a finite number");
  if (!goal.allFinite()) return R::failure(PlanStatus::kInvalidInput, "goal pose is not a finite number");
  if (!start_velocity.allFinite())
    return R::failure(PlanStatus::kInvalidInput, "start velocity is not a finite number");
  if (!model_.withinLimits(start)) {
    return R::failure(PlanStatus::kStartOutOfRange,
                      "start " + poseText(model_, start) + " is outside the joint limits: " + rangeText(model_));
  }
  if (!model_.withinLimits(goal)) {
    return R::failure(PlanStatus::kGoalOutOfRange,
                      "goal " + poseText(model_, goal) + " is outside the joint limits: " + rangeText(model_));
  }
  const CollisionWorld& world = worlds_[static_cast<size_t>(pieces.index())];
  const CSpaceGrid& grid = this->grid(pieces);
  const double clearance = model_.clearance_m;
  const JointVector& metric = model_.planner.metric;
  const SmoothingSettings& smoothing = model_.planner.smoothing;
  auto too_close = [&](const char* which, const JointVector& q, const SignedDistance& d) {
    return fmt::format("{} {} is {:.4f} m from {} (clearance {:.4f} m)", which, poseText(model_, q), d.value,
                       obstacleName(scene_, d.obstacle), clearance);
  };
  const SignedDistance d_start = world.distance(start);
  if (d_start.value < clearance) return R::failure(PlanStatus::kStartInCollision, too_close("start", start, d_start));
  const SignedDistance d_goal = world.distance(goal);
  if (d_goal.value < clearance) return R::failure(PlanStatus::kGoalInCollision, too_close("goal", goal, d_goal));

  const Clock::time_point t_search = Clock::now();
  PlannedPath out;
  out.pieces = pieces;
  const double start_speed = weightedNorm(start_velocity, metric);
  if (weightedNorm(goal - start, metric) < kSamePose && start_speed == 0.0) {
    const std::vector<JointVector> single{start};
    auto trivial = CubicSplinePath::through(single, metric);
    if (!trivial.ok()) return trivial.error();
    out.path = std::make_shared<const CubicSplinePath>(std::move(trivial).value());
    out.waypoints = out.search_waypoints = single;
    out.min_clearance_m = d_start.value;
    out.direct = true;
    out.method = "zero-length";
    out.search_ms = millisecondsSince(t_search);
    return std::vector<PlannedPath>{out};
  }

  // Lead-in: a straight piece along the start velocity, shortened until it is inside the limits
  // and clear (or dropped).
  std::vector<JointVector> polyline{start};
  JointVector from = start;
  if (start_speed > 0.0) {
    const JointVector direction = start_velocity / start_speed;
    double lead = std::min(smoothing.max_lead_in, start_speed * smoothing.lead_in_time_s);
    for (int attempt = 0; attempt <= kLeadInHalvings && lead > kSamePose; ++attempt, lead *= 0.5) {
      const JointVector candidate = start + lead * direction;
      if (model_.withinLimits(candidate) && checkSegment(world, start, candidate, clearance).clear) {
        from = candidate;
        polyline.push_back(candidate);
        out.lead_in = true;
        break;
      }
    }
  }

  std::vector<int> first_cells;
  double first_cost = 0.0;  // in the search's metric
  std::vector<SearchEndpoint> source_links, goal_links;
  if (checkSegment(world, from, goal, clearance).clear) {
    out.direct = true;
    polyline.push_back(goal);
  } else {
    const std::vector<SearchEndpoint> sources = connectToGrid(grid, world, from, clearance);
    if (sources.empty()) {
      return R::failure(PlanStatus::kNoPath, "no free grid node near the start " + poseText(model_, from) +
                                                 " can be reached in a straight line with the clearance");
    }
    const std::vector<SearchEndpoint> goals = connectToGrid(grid, world, goal, clearance);
    if (goals.empty()) {
      return R::failure(PlanStatus::kNoPath, "no free grid node near the goal " + poseText(model_, goal) +
                                                 " can be reached in a straight line with the clearance");
    }
    const auto found = astarSearch(grid, sources, goals, goal);
    if (!found) {
      return R::failure(PlanStatus::kNoPath, "the goal " + poseText(model_, goal) + " cannot be reached from " +
                                                 poseText(model_, from) + " without coming closer than the clearance");
    }
    out.search_expanded = found->expanded;
    for (int cell : found->cells) polyline.push_back(grid.node(cell));
    polyline.push_back(goal);
    first_cells = found->cells;
    first_cost = found->cost;
    source_links = sources;
    goal_links = goals;
  }
  out.search_waypoints = polyline;
  out.search_ms = millisecondsSince(t_search);

  // Smoothing: resample, optimise (eq. 8), spline, continuous check; weaker smoothing on failure.
  // Done for the search's polyline and for its shortcut (docs/performance.md, "Choosing the path
  // for time"); the one the reachability pass times faster is kept.
  const Clock::time_point t_smooth = Clock::now();
  const int fixed_head = out.lead_in ? 2 : 1;
  ClearanceCheck last_check;
  auto smooth = [&](const std::vector<JointVector>& line, const char* label, PlannedPath& into) {
    const std::vector<JointVector> tail(line.begin() + fixed_head - 1, line.end());
    auto prior_at = [&](double spacing) {
      std::vector<JointVector> prior(line.begin(), line.begin() + fixed_head - 1);
      const std::vector<JointVector> resampled = resamplePolyline(tail, metric, spacing);
      prior.insert(prior.end(), resampled.begin(), resampled.end());
      return prior;
    };
    auto accept = [&](const std::vector<JointVector>& waypoints, const std::string& method) {
      auto spline = CubicSplinePath::through(waypoints, metric, start_velocity);
      if (!spline.ok()) return false;
      last_check = checkPath(spline.value(), world, model_, clearance);
      if (!last_check.ok()) return false;
      into.path = std::make_shared<const CubicSplinePath>(std::move(spline).value());
      into.waypoints = waypoints;
      into.min_clearance_m = last_check.min_distance_m;
      into.method = label + method;
      return true;
    };
    if (out.direct && !out.lead_in) return accept(line, "straight");
    const std::vector<JointVector> prior = prior_at(smoothing.waypoint_spacing);
    const SmoothingResult optimised = optimizePath(world, prior, fixed_head, model_, smoothing);
    into.optimizer_iterations += optimised.lbfgs.iterations;
    if (accept(optimised.waypoints, "optimised")) return true;
    SmoothingSettings stronger = smoothing;
    stronger.obstacle_weight *= 10.0;
    const SmoothingResult pushed = optimizePath(world, prior, fixed_head, model_, stronger);
    into.optimizer_iterations += pushed.lbfgs.iterations;
    if (accept(pushed.waypoints, "optimised, obstacle weight x10")) return true;
    if (accept(prior, "prior")) return true;
    return accept(prior_at(0.25 * smoothing.waypoint_spacing), "dense prior");
  };
  const bool done = smooth(polyline, "", out);
  std::vector<PlannedPath> candidates;
  if (done) candidates.push_back(out);
  const DriveModel drives = model_.driveModel(pieces);
  const double b_start = start_speed * start_speed;
  // The shape search from `knots` (through which `fastest` runs), put first when it is faster.
  // `path` through `waypoints` put first, in `fastest`'s place, when an estimate on a finer grid
  // than the searches' own confirms it faster (a coarse estimate can be fooled between its points).
  // fastest_s: `fastest`'s estimate on that grid.
  auto put_first_if_faster = [&](const PlannedPath& fastest, double fastest_s, CubicSplinePath path,
                                 std::vector<JointVector> waypoints, double min_clearance_m, std::string method) {
    if (!(estimateDuration(path, drives, b_start, kShapeCheckGridPoints) < (1.0 - kShapeGain) * fastest_s)) return;
    PlannedPath better = fastest;
    better.path = std::make_shared<const CubicSplinePath>(std::move(path));
    better.waypoints = std::move(waypoints);
    better.min_clearance_m = min_clearance_m;
    better.method = std::move(method);
    candidates.insert(candidates.begin(), std::move(better));
  };
  // The shape search from `knots` (through which `fastest` runs), refined further when its shape
  // is still estimated well above the slower joint moving alone.
  auto add_shaped = [&](const PlannedPath& fastest, const std::vector<JointVector>& knots) {
    ShapedPath shaped = shapeForTime(knots, fixed_head, start_velocity, world, model_, b_start, ShapeSearchSettings{});
    const ShapeRefinementSettings refinement;
    if (shaped.estimate_s > kRefineRatio * slowerJointAlone(from, goal, metric, drives, refinement.grid_points)) {
      ShapedPath refined =
          refineShapeForTime(shaped.waypoints, fixed_head, start_velocity, world, model_, b_start, refinement);
      if (refined.improvements > 0) {
        refined.improvements += shaped.improvements;
        shaped = std::move(refined);
      }
    }
    if (shaped.improvements == 0) return;
    put_first_if_faster(fastest, estimateDuration(*fastest.path, drives, b_start, kShapeCheckGridPoints),
                        std::move(shaped.path), std::move(shaped.waypoints), shaped.min_clearance_m,
                        "shaped for time, " + fastest.method);
  };
  if (out.direct && done && alternatives == PathAlternatives::kSearch) {
    // A straight segment is not the fastest path when the joints' limits differ (gravity, voltage
    // limits): the shape search bends it, from knots spread evenly along it.
    const std::vector<JointVector> tail(polyline.begin() + fixed_head - 1, polyline.end());
    std::vector<JointVector> knots(polyline.begin(), polyline.begin() + fixed_head - 1);
    const double tail_length = weightedNorm(tail.back() - tail.front(), metric);
    const std::vector<JointVector> spread = resamplePolyline(tail, metric, tail_length / (kDirectShapeKnots - 1));
    knots.insert(knots.end(), spread.begin(), spread.end());
    // Only when the segment is estimated slower than its slower joint moving alone: otherwise that
    // joint's limits bind all along and no shape can be faster.
    if (straightEstimate(from, goal, metric, drives, kGateGridPoints) >
        kDirectShapeRatio * slowerJointAlone(from, goal, metric, drives))
      add_shaped(candidates.front(), knots);
  }
  if (!out.direct && alternatives == PathAlternatives::kSearch) {
    std::vector<double> estimates;
    for (const PlannedPath& c : candidates)
      estimates.push_back(estimateDuration(*c.path, drives, b_start, kTimingGridPoints));
    // Adds the polyline's shortcut (or the polyline itself) in the order of estimated time.
    auto add = [&](const std::vector<JointVector>& line, const char* label) {
      PlannedPath alternative = out;
      if (!smooth(line, label, alternative)) return;
      const double seconds = estimateDuration(*alternative.path, drives, b_start, kTimingGridPoints);
      size_t at = 0;
      while (at < estimates.size() && estimates[at] <= seconds) ++at;
      estimates.insert(estimates.begin() + static_cast<long>(at), seconds);
      candidates.insert(candidates.begin() + static_cast<long>(at), std::move(alternative));
    };
    const std::vector<JointVector> shortcut =
        shortcutPolyline(world, polyline, fixed_head, clearance + kShortcutMargin_m);
    if (shortcut.size() < polyline.size()) add(shortcut, "shortcut, ");
    const double straight_s = straightEstimate(from, goal, metric, drives);
    if (!estimates.empty() && estimates.front() > kDetourRatio * straight_s) {
      auto add_search = [&](const std::optional<SearchPath>& found, const char* label) {
        if (!found) return;
        std::vector<JointVector> around(polyline.begin(), polyline.begin() + fixed_head);
        for (int cell : found->cells) around.push_back(grid.node(cell));
        around.push_back(goal);
        add(shortcutPolyline(world, around, fixed_head, clearance + kShortcutMargin_m), label);
      };
      // Without a hole the other way round is the search with the first path's band blocked;
      // with holes, the other side of each (the band also blocks a narrow corridor both ways share,
      // leaving a low pose with a piece held for example, and finds nothing).
      const std::vector<GridHole>& holes = grid.holes();
      if (holes.empty()) {
        const std::vector<std::uint8_t> band = bandAround(grid, first_cells, kBandRadius);
        add_search(astarSearch(grid, source_links, goal_links, goal, SearchOptions{.also_blocked = band}),
                   "other way round, ");
      }
      for (size_t h = 0; h < std::min(holes.size(), kMaxHoleSides); ++h) {
        const SideOfHole other_side{holes[h], 1 - rayCrossingParity(grid, holes[h], first_cells)};
        add_search(astarSearch(grid, source_links, goal_links, goal,
                               SearchOptions{.side = other_side, .max_cost = kMaxSideCost * first_cost}),
                   "other side, ");
      }
    }
    if (!estimates.empty() && estimates.front() > kShapeRatio * straight_s) {
      const PlannedPath fastest = candidates.front();
      add_shaped(fastest, fastest.waypoints);
    }
  }
  if (!candidates.empty() && start_speed == 0.0 && alternatives == PathAlternatives::kSearch) {
    // The joints' own fastest motions side by side (synchronised_path.hpp). A coarser estimate of
    // the slower joint alone first: the joints' own profiles cost five times as much, and half the
    // public moves are already within a per cent of it.
    const PlannedPath fastest = candidates.front();
    const double fastest_s = estimateDuration(*fastest.path, drives, 0.0, kShapeCheckGridPoints);
    const double slower_alone_s = slowerJointAlone(start, goal, metric, drives, kTimingGridPoints);
    if (fastest_s > kSynchronisedRatio * slower_alone_s && fastest_s < kSynchronisedMaxRatio * slower_alone_s) {
      if (auto synchronised = synchronisedPath(start, goal, world, model_, fastest_s / kSynchronisedRatio)) {
        put_first_if_faster(fastest, fastest_s, std::move(synchronised->path), std::move(synchronised->waypoints),
                            synchronised->min_clearance_m, "synchronised joints");
      }
    }
  }
  const double smooth_ms = millisecondsSince(t_smooth);
  for (PlannedPath& candidate : candidates) candidate.smooth_ms = smooth_ms;
  if (candidates.empty()) {
    return R::failure(
        PlanStatus::kClearanceNotMet,
        fmt::format("no smoothed path keeps the clearance {:.4f} m and the joint limits (last attempt: {}, {:.4f} m at "
                    "s = {:.4f})",
                    clearance, last_check.within_limits ? "closest" : "outside the limits", last_check.min_distance_m,
                    last_check.at_s));
  }
  return candidates;
}

Result<PlannedPath> PathPlanner::plan(const JointVector& start, const JointVector& goal, HeldPieces pieces,
                                      const JointVector& start_velocity) const {
  Result<std::vector<PlannedPath>> found = candidates(start, goal, pieces, start_velocity);
  if (!found) return found.error();
  return std::move(found.value().front());
}

}  // namespace cyber::planner

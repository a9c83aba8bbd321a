#include "path/path_planner.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <future>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "elapsed_ms.hpp"
#include "math/weighted_norm.hpp"
#include "path/astar_search.hpp"
#include "path/path_clearance.hpp"
#include "path/strategies/path_strategies.hpp"

namespace cyber::planner {
namespace {

using Clock = std::chrono::steady_clock;

std::string poseText(const RobotModel& model, const JointVector& q) {
  std::string out = "(";
  for (int j = 0; j < q.size(); ++j) {
    out += fmt::format("{}{:.4f} {}", j == 0 ? "" : ", ", q[j], unitName(model.joints[j].type));
  }
  return out + ")";
}

std::string rangeText(const RobotModel& model) {
  std::string out;
  for (int j = 0; j < model.jointCount(); ++j) {
    out += fmt::format("{}{} [{:.4f}, {:.4f}]", j == 0 ? "" : ", ", model.joints[j].name, model.range(j).min,
                       model.range(j).max);
  }
  return out;
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

constexpr int kMaxConnectionRing = 4;  // nodes up to this many steps from a pose may be connected
constexpr int kLeadInHalvings = 5;

// Free grid nodes near a pose that a straight, clear segment reaches, with the connection cost
// |segment|_Sigma (1 + w p(node) / 2) >= |segment|_Sigma (what A*'s heuristic needs). Tries the
// 2^N nodes around the pose first and widens ring by ring.
std::vector<SearchEndpoint> connectToGrid(const CSpaceGrid& grid, const CollisionWorld& world, const JointVector& pose,
                                          double clearance_m) {
  std::vector<SearchEndpoint> out;
  const GridIndex corner = grid.indices(grid.lowerCorner(pose));
  for (int ring = 1; ring <= kMaxConnectionRing && out.empty(); ++ring) {
    GridIndex lo{}, hi{};
    for (size_t d = 0; d < static_cast<size_t>(grid.dimensions()); ++d) {
      lo[d] = corner[d] - ring + 1;
      hi[d] = corner[d] + ring;
    }
    grid.forEachInBox(lo, hi, [&](const GridIndex& idx, int cell) {
      // Only the new ring: the inner nodes were tried already.
      bool inner = true;
      for (size_t d = 0; d < static_cast<size_t>(grid.dimensions()); ++d)
        inner = inner && idx[d] > lo[d] && idx[d] < hi[d];
      if (ring > 1 && inner) return;
      if (grid.blocked(cell)) return;
      if (!checkSegment(world, pose, grid.node(cell), clearance_m).clear) return;
      const double length = weightedNorm(grid.node(cell) - pose, grid.metric());
      out.push_back({cell, length * (1.0 + 0.5 * grid.potentialWeight() * grid.potential(cell))});
    });
  }
  return out;
}

}  // namespace

PathPlanner::PathPlanner(const RobotModel& model, const Scene& scene, const JointRange& band)
    : model_(model), scene_(scene), band_(band) {
  const int sets = model_.pieceSetCount();
  auto grids = std::make_shared<Grids>();
  grids->grids.resize(static_cast<size_t>(sets));
  grids->build_ms.assign(static_cast<size_t>(sets), 0.0);
  const double centre = 0.5 * (band.min + band.max);
  worlds_ = worldsAt(centre);
  // The sets' grids are independent (const worlds, no shared state): two threads take the next
  // set until none is left, which halves the first start on a two-core controller
  // (docs/performance.md, "Start-up").
  std::atomic<int> next{0};
  const auto build_sets = [&] {
    for (int set = next++; set < sets; set = next++) {
      const Clock::time_point t0 = Clock::now();
      const auto index = static_cast<size_t>(set);
      // A band wider than one offset searches the world swept over it; its checks use one offset.
      grids->grids[index] =
          band.max > band.min
              ? CSpaceGrid::build(CollisionWorld(model_, scene_, HeldPieces::fromIndex(set), band), model_)
              : CSpaceGrid::build(worlds_[index], model_);
      grids->build_ms[index] = msSince(t0);
    }
  };
  std::future<void> helper;
  try {
    helper = std::async(std::launch::async, build_sets);
  } catch (const std::system_error&) {
    // No thread to be had (a process limit): this one builds every set.
  }
  build_sets();
  if (helper.valid()) helper.get();
  grids_ = std::move(grids);
}

PathPlanner::PathPlanner(const RobotModel& model, const Scene& scene, const JointRange& band,
                         std::vector<CSpaceGrid> grids)
    : model_(model), scene_(scene), band_(band) {
  auto shared = std::make_shared<Grids>();
  shared->build_ms.assign(grids.size(), 0.0);
  shared->grids = std::move(grids);
  worlds_ = worldsAt(0.5 * (band.min + band.max));
  grids_ = std::move(shared);
}

PathPlanner PathPlanner::atOffset(double scene_offset_m) const {
  PathPlanner out(*this);
  out.worlds_ = worldsAt(scene_offset_m);
  return out;
}

std::vector<CollisionWorld> PathPlanner::worldsAt(double scene_offset_m) const {
  std::vector<CollisionWorld> worlds;
  worlds.reserve(static_cast<size_t>(model_.pieceSetCount()));
  for (int set = 0; set < model_.pieceSetCount(); ++set) {
    worlds.emplace_back(model_, scene_, HeldPieces::fromIndex(set), scene_offset_m);
  }
  return worlds;
}

Result<std::vector<PlannedPath>> PathPlanner::candidates(const JointVector& start, const JointVector& goal,
                                                         HeldPieces pieces, const JointVector& start_velocity,
                                                         PathAlternatives alternatives) const {
  const std::span<const PathStrategy> all = pathStrategies();
  return candidates(start, goal, pieces, start_velocity,
                    alternatives == PathAlternatives::kSearch ? all : all.first(0));
}

std::optional<PlanError> PathPlanner::checkEndpoints(const JointVector& start, const JointVector& goal,
                                                     const JointVector& start_velocity,
                                                     const CollisionWorld& world) const {
  if (!start.allFinite()) return PlanError{PlanStatus::kInvalidInput, "start pose is not a finite number"};
  if (!goal.allFinite()) return PlanError{PlanStatus::kInvalidInput, "goal pose is not a finite number"};
  if (!start_velocity.allFinite()) return PlanError{PlanStatus::kInvalidInput, "start velocity is not a finite number"};
  if (!model_.withinLimits(start)) {
    return PlanError{PlanStatus::kStartOutOfRange,
                     "start " + poseText(model_, start) + " is outside the joint limits: " + rangeText(model_)};
  }
  if (!model_.withinLimits(goal)) {
    return PlanError{PlanStatus::kGoalOutOfRange,
                     "goal " + poseText(model_, goal) + " is outside the joint limits: " + rangeText(model_)};
  }
  const double clearance = model_.clearance_m;
  auto too_close = [&](const char* which, const JointVector& q, const SignedDistance& d) {
    return fmt::format("{} {} is {:.4f} m from {} (clearance {:.4f} m)", which, poseText(model_, q), d.value,
                       obstacleName(scene_, d.obstacle), clearance);
  };
  const SignedDistance d_start = world.distance(start);
  if (d_start.value < clearance) return PlanError{PlanStatus::kStartInCollision, too_close("start", start, d_start)};
  const SignedDistance d_goal = world.distance(goal);
  if (d_goal.value < clearance) return PlanError{PlanStatus::kGoalInCollision, too_close("goal", goal, d_goal)};
  return std::nullopt;
}

// A straight piece along the start velocity, shortened until it is inside the limits and clear
// (or dropped): appended to `polyline`, and its end returned (the start when there is none).
JointVector PathPlanner::leadIn(const JointVector& start, const JointVector& start_velocity,
                                const CollisionWorld& world, std::vector<JointVector>& polyline,
                                PlannedPath& out) const {
  const double start_speed = weightedNorm(start_velocity, model_.planner.metric);
  if (!(start_speed > 0.0)) return start;
  const SmoothingSettings& smoothing = model_.planner.smoothing;
  const JointVector direction = start_velocity / start_speed;
  double lead = std::min(smoothing.max_lead_in, start_speed * smoothing.lead_in_time_s);
  for (int attempt = 0; attempt <= kLeadInHalvings && lead > kSamePoseWeighted; ++attempt, lead *= 0.5) {
    const JointVector candidate = start + lead * direction;
    if (model_.withinLimits(candidate) && checkSegment(world, start, candidate, model_.clearance_m).clear) {
      polyline.push_back(candidate);
      out.lead_in = true;
      return candidate;
    }
  }
  return start;
}

// The first path from `from` (the lead-in's end): the straight segment when it is clear, else the
// grid search's cells with its connections. A refusal quotes the start asked for, and the lead-in's
// end when there is one (the search starts there).
Result<PathPlanner::FirstSearch> PathPlanner::searchFirstPath(const JointVector& start, const JointVector& from,
                                                              const JointVector& goal, const CollisionWorld& world,
                                                              const CSpaceGrid& grid) const {
  const double clearance = model_.clearance_m;
  FirstSearch out;
  if (checkSegment(world, from, goal, clearance).clear) {
    out.direct = true;
    return out;
  }
  std::string start_text = poseText(model_, start);
  if (from != start) start_text.append(" (after its lead-in to ").append(poseText(model_, from)).append(")");
  out.sources = connectToGrid(grid, world, from, clearance);
  if (out.sources.empty()) {
    return PlanError{PlanStatus::kNoPath, fmt::format("no free grid node near the start {} can be reached in a "
                                                      "straight line with the clearance",
                                                      start_text)};
  }
  out.goals = connectToGrid(grid, world, goal, clearance);
  if (out.goals.empty()) {
    return PlanError{PlanStatus::kNoPath, "no free grid node near the goal " + poseText(model_, goal) +
                                              " can be reached in a straight line with the clearance"};
  }
  const auto found = astarSearch(grid, out.sources, out.goals, goal);
  if (!found) {
    return PlanError{PlanStatus::kNoPath,
                     fmt::format("the goal {} cannot be reached from {} without coming closer than the clearance",
                                 poseText(model_, goal), start_text)};
  }
  out.cells = found->cells;
  out.cost = found->cost;
  out.expanded = found->expanded;
  return out;
}

// The start and goal as one pose, at rest: the path that stays there.
Result<std::vector<PlannedPath>> PathPlanner::stayingPath(const JointVector& start, double start_distance_m,
                                                          PlannedPath out) const {
  const std::vector<JointVector> single{start};
  auto trivial = CubicSplinePath::through(single, model_.planner.metric);
  if (!trivial.ok()) return trivial.error();
  out.path = std::make_shared<const CubicSplinePath>(std::move(trivial).value());
  out.waypoints = out.search_waypoints = single;
  out.min_clearance_m = start_distance_m;
  out.direct = true;
  out.method.smoothing = PlanMethod::Smoothing::kStaying;
  return std::vector<PlannedPath>{out};
}

Result<std::vector<PlannedPath>> PathPlanner::candidates(const JointVector& start, const JointVector& goal,
                                                         HeldPieces pieces, const JointVector& start_velocity,
                                                         std::span<const PathStrategy> strategies) const {
  const CollisionWorld& world = worlds_[static_cast<size_t>(pieces.index())];
  if (auto refused = checkEndpoints(start, goal, start_velocity, world)) return *refused;
  const JointVector& metric = model_.planner.metric;
  const Clock::time_point t_search = Clock::now();
  PlannedPath out;
  out.pieces = pieces;
  const double start_speed = weightedNorm(start_velocity, metric);
  if (weightedNorm(goal - start, metric) < kSamePoseWeighted && start_speed == 0.0) {
    out.search_ms = msSince(t_search);
    return stayingPath(start, world.distance(start).value, std::move(out));
  }
  std::vector<JointVector> polyline{start};
  const JointVector from = leadIn(start, start_velocity, world, polyline, out);
  // A band's grid is blocked by the field elements swept across the band: where it finds no path,
  // the exact offset's own grid decides (docs/algorithm.md section 2, "Scene offsets").
  std::optional<CSpaceGrid> exact_grid;
  Result<FirstSearch> first = searchFirstPath(start, from, goal, world, grid(pieces));
  if (!first && band_.max > band_.min) {
    exact_grid = CSpaceGrid::build(world, model_);
    first = searchFirstPath(start, from, goal, world, *exact_grid);
    out.exact_offset_grid = true;
  }
  if (!first) return first.error();
  const CSpaceGrid& searched = exact_grid ? *exact_grid : grid(pieces);
  for (int cell : first.value().cells) polyline.push_back(searched.node(cell));
  polyline.push_back(goal);
  out.direct = first.value().direct;
  out.search_expanded = first.value().expanded;
  CandidateInputs inputs{.model = model_,
                         .world = world,
                         .grid = searched,
                         .drives = model_.driveModel(pieces),
                         .start = start,
                         .goal = goal,
                         .start_velocity = start_velocity,
                         .b_start = start_speed * start_speed,
                         .polyline = std::move(polyline),
                         .fixed_head = out.lead_in ? 2 : 1,
                         .direct = out.direct,
                         .first_cells = std::move(first.value().cells),
                         .first_cost = first.value().cost,
                         .source_links = std::move(first.value().sources),
                         .goal_links = std::move(first.value().goals),
                         .straight_estimate_s = 0.0,
                         .first = {}};
  out.search_waypoints = inputs.polyline;
  out.search_ms = msSince(t_search);
  inputs.first = out;
  return smoothedCandidates(inputs, strategies);
}

// The first path smoothed, then the strategies' candidates (docs/algorithm.md section 2.6); the
// one the reachability pass times fastest comes first.
Result<std::vector<PlannedPath>> PathPlanner::smoothedCandidates(CandidateInputs& inputs,
                                                                 std::span<const PathStrategy> strategies) const {
  const Clock::time_point t_smooth = Clock::now();
  CandidateList list;
  if (smoothPolyline(inputs, inputs.polyline, inputs.first, list)) list.putFirst(inputs.first);
  if (!strategies.empty() && !inputs.direct) {
    inputs.straight_estimate_s = straightEstimate(inputs.from(), inputs.goal, inputs.drives, model_.planner.metric,
                                                  model_.planner.strategies.timing_grid_points);
  }
  for (const PathStrategy& strategy : strategies) {
    list.adding_for = strategy.name;
    strategy.run(inputs, list);
  }
  const ClearanceCheck& last_check = list.last_check;
  std::vector<PlannedPath> candidates = list.release();
  const double smooth_ms = msSince(t_smooth);
  for (PlannedPath& candidate : candidates) candidate.smooth_ms = smooth_ms;
  if (candidates.empty()) {
    return Result<std::vector<PlannedPath>>::failure(
        PlanStatus::kClearanceNotMet,
        fmt::format("no smoothed path keeps the clearance {:.4f} m and the joint limits (last attempt: {}, {:.4f} m at "
                    "s = {:.4f})",
                    model_.clearance_m, last_check.within_limits ? "closest" : "outside the limits",
                    last_check.min_distance_m, last_check.at_s));
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

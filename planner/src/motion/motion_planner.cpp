#include "cyber/planner/motion_planner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "elapsed_ms.hpp"
#include "math/weighted_norm.hpp"
#include "motion/fastest_stop.hpp"
#include "motion/moving_start_strategies.hpp"
#include "motion/scene_planners.hpp"
#include "motion/timed_plan.hpp"
#include "path/clearance_escape.hpp"
#include "path/grid_cache.hpp"

namespace cyber::planner {
namespace {

// Bands of scene offsets are never narrower than this [m]: a zero band width would mean infinitely
// many sets of grids.
constexpr double kNarrowestBandM = 1e-3;
// An offset within this of a range's or band's end [m] is inside: the roundoff of a requested value.
constexpr double kOffsetRoundoffM = 1e-9;

// A start at rest inside the clearance that touches nothing: out along the steepest way, then
// the rest-to-rest plan from there (docs/algorithm.md section 5). `refused` is the path stage's
// own answer, kept when there is no way out.
Result<Plan> escapeThenPlan(const RobotModel& model, const PathPlanner& paths, const PlanRequest& request,
                            Result<Plan> refused) {
  ToppSolver solver(model.planner.topp);
  const CollisionWorld& world = paths.world(request.pieces);
  Result<Trajectory> escape = clearanceEscape(model, world, request.start, solver);
  if (!escape) {
    return Result<Plan>::failure(PlanStatus::kStartInCollision,
                                 fmt::format("{}; {}", refused.error().message, escape.error().message));
  }
  const Result<Plan> onward = timedPath(model, paths, restOf(escape.value()), request.goal, request.pieces,
                                        JointVector::Zero(model.jointCount()));
  Result<Plan> plan = joinAfter(PlanMethod::kLeftTheClearance, request, escape.value(), onward);
  // The way out is a few millimetres, timed in tens of milliseconds: its switch from accelerating
  // to braking, and the jump at the junction, are large next to its peak speed, so its columns
  // may disagree at 1 ms as a short move's do. It is slowed as one is (consistentSlowdown), by
  // fractions of a step, until the joined columns agree.
  const MotionSettings& settings = model.planner.motion;
  if (plan && !columnsAgree(settings, *plan.value().trajectory)) {
    Result<Plan> joined = plan;
    const auto joined_agrees = [&](const Trajectory& slower) {
      joined = joinAfter(PlanMethod::kLeftTheClearance, request, slower, onward);
      return joined && columnsAgree(settings, *joined.value().trajectory);
    };
    if (shortestSlowdown(model, escape.value(), settings.escape_slower_steps, joined_agrees)) plan = std::move(joined);
  }
  if (plan) plan.value().min_clearance_m = std::min(plan.value().min_clearance_m, world.distance(request.start).value);
  return plan;
}

// kInvalidInput when the start, the goal (`with_goal`) or the start velocity has not one value per
// joint (an empty start velocity is a start at rest).
std::optional<PlanError> checkJointCounts(const RobotModel& robot, const PlanRequest& request, bool with_goal) {
  const int n = robot.jointCount();
  const auto wrong = [&](const char* what, const JointVector& v) {
    return PlanError{PlanStatus::kInvalidInput,
                     fmt::format("the {} has {} values; this robot has {} joints", what, v.size(), n)};
  };
  if (request.start.size() != n) return wrong("start pose", request.start);
  if (with_goal && request.goal.size() != n) return wrong("goal pose", request.goal);
  if (request.start_velocity.size() != n && request.start_velocity.size() != 0)
    return wrong("start velocity", request.start_velocity);
  return std::nullopt;
}

// kInvalidInput for an unknown scene, or an offset that is not finite or outside the scene's range.
std::optional<PlanError> checkSceneAndOffset(const RobotModel& robot, const PlanRequest& request) {
  if (request.scene < 0 || request.scene >= static_cast<int>(robot.scenes.size())) {
    return PlanError{PlanStatus::kInvalidInput, fmt::format("unknown scene index {}", request.scene)};
  }
  const Scene& scene = robot.scenes[static_cast<size_t>(request.scene)];
  const double offset = request.scene_offset_m;
  if (!std::isfinite(offset) || !scene.offset_range_m.contains(offset, kOffsetRoundoffM)) {
    return PlanError{PlanStatus::kInvalidInput,
                     fmt::format("scene offset {:.4f} m is outside scene {}'s range [{:.4f}, {:.4f}] m", offset,
                                 scene.name, scene.offset_range_m.min, scene.offset_range_m.max)};
  }
  return std::nullopt;
}

// The path stage of the request's scene at its offset: the scene as drawn, or the band of grids
// that holds the offset with the exact offset's worlds (in `shifted`). kInvalidInput for a
// request checkSceneAndOffset refuses, a start velocity that is not finite, or grids a
// GridSelection left out.
Result<const PathPlanner*> pathsFor(const RobotModel& robot, const std::vector<std::vector<PathPlanner>>& planners,
                                    const PlanRequest& request, std::optional<PathPlanner>& shifted) {
  using R = Result<const PathPlanner*>;
  if (auto refused = checkSceneAndOffset(robot, request)) return *refused;
  if (!request.start_velocity.allFinite()) return R::failure(PlanStatus::kInvalidInput, "start velocity is not finite");
  const Scene& scene = robot.scenes[static_cast<size_t>(request.scene)];
  const double offset = request.scene_offset_m;
  const std::vector<PathPlanner>& bands = planners[static_cast<size_t>(request.scene)];
  const bool drawn = offset == 0.0 || scene.obstacles.empty();
  const auto base = std::find_if(bands.begin(), bands.end(), [&](const PathPlanner& p) {
    const JointRange& band = p.band();
    return drawn ? band.min == 0.0 && band.max == 0.0 : band.max > band.min && band.contains(offset, kOffsetRoundoffM);
  });
  if (base == bands.end()) {
    return R::failure(
        PlanStatus::kInvalidInput,
        fmt::format("this planner was built without the grids of scene {} at offset {:.4f} m", scene.name, offset));
  }
  if (drawn) return &*base;
  shifted = base->atOffset(offset);
  return &*shifted;
}

}  // namespace

Result<MotionPlanner> MotionPlanner::create(const RobotModel& model, const GridSelection& selection,
                                            const std::optional<std::filesystem::path>& cache_dir) {
  if (model.scenes.empty()) return Result<MotionPlanner>::failure(PlanStatus::kInvalidInput, "the robot has no scene");
  const int n = model.jointCount();
  if (n < 1 || n > kMaxJoints) {
    return Result<MotionPlanner>::failure(PlanStatus::kInvalidInput,
                                          fmt::format("the robot has {} joints; 1 to {} are planned", n, kMaxJoints));
  }
  if (model.drives.size() != n || model.planner.metric.size() != n || model.planner.grid.step.size() != n ||
      (model.drive_kind == DriveKind::kRigidBody && model.bodies.size() != n)) {
    return Result<MotionPlanner>::failure(
        PlanStatus::kInvalidInput, "the drives, bodies, metric and grid step need one entry per joint of the chain");
  }
  bool has_polygon = false;
  for (const LinkGeometry& link : model.links) has_polygon = has_polygon || !link.polygons.empty();
  if (!has_polygon) return Result<MotionPlanner>::failure(PlanStatus::kInvalidInput, "the robot has no link polygons");
  if (static_cast<int>(model.pieces.size()) > HeldPieces::kMaxPieces) {
    return Result<MotionPlanner>::failure(PlanStatus::kInvalidInput,
                                          fmt::format("at most {} game pieces", HeldPieces::kMaxPieces));
  }
  auto scenes = std::make_shared<Scenes>();
  scenes->model = model;
  scenes->path_planners.reserve(model.scenes.size());
  const double band_width = model.planner.search.offset_band_clearances * model.clearance_m;
  for (size_t index = 0; index < model.scenes.size(); ++index) {
    const Scene& scene = model.scenes[index];
    std::vector<PathPlanner>& bands = scenes->path_planners.emplace_back();
    if (selection.scene >= 0 && selection.scene != static_cast<int>(index)) continue;
    const bool moves = !scene.obstacles.empty();
    const std::optional<double>& only = selection.scene_offset_m;
    const auto scene_index = static_cast<int>(index);
    if (!only || *only == 0.0 || !moves) {
      bands.push_back(cachedPathPlanner(model, scene_index, 0, JointRange{}, cache_dir).planner);
    }
    const JointRange& range = scene.offset_range_m;
    const double span = range.max - range.min;
    if (span <= 0.0 || !moves) continue;
    const int count = std::max(1, static_cast<int>(std::ceil(span / std::max(band_width, kNarrowestBandM))));
    for (int k = 0; k < count; ++k) {
      const JointRange band{range.min + span * k / count,
                            k + 1 == count ? range.max : range.min + span * (k + 1) / count};
      if (only && (*only == 0.0 || !band.contains(*only))) continue;
      bands.push_back(cachedPathPlanner(model, scene_index, k + 1, band, cache_dir).planner);
      if (only) break;
    }
  }
  return MotionPlanner(std::move(scenes));
}

const RobotModel& MotionPlanner::model() const { return scenes_->model; }

const PathPlanner& drawnPathPlanner(const MotionPlanner& planner, int scene) {
  return planner.scenes_->path_planners[static_cast<size_t>(scene)].front();
}

std::vector<JointRange> MotionPlanner::offsetBands(int scene) const {
  std::vector<JointRange> out;
  if (scene < 0 || scene >= static_cast<int>(scenes_->path_planners.size())) return out;
  for (const PathPlanner& band : scenes_->path_planners[static_cast<size_t>(scene)]) out.push_back(band.band());
  return out;
}

Result<Plan> MotionPlanner::stop(const PlanRequest& request) const {
  const auto start_time = std::chrono::steady_clock::now();
  const RobotModel& robot = model();
  if (auto refused = checkSceneAndOffset(robot, request)) return *refused;
  if (auto refused = checkJointCounts(robot, request, false)) return *refused;
  if (request.start_velocity.size() == 0) return PlanError{PlanStatus::kInvalidInput, "no velocity to stop from"};
  ToppSolver solver(robot.planner.topp);
  // The world the braked motion was planned in: the scene as drawn, or shifted by its offset. A
  // stop needs no grid, so it is made for any scene, whichever grids the planner was built with.
  const CollisionWorld world(robot, robot.scenes[static_cast<size_t>(request.scene)], request.pieces,
                             request.scene_offset_m);
  Result<Trajectory> braked = fastestStop(robot, world, request.start, request.start_velocity, solver);
  if (!braked) return braked.error();
  Plan plan;
  plan.trajectory = std::make_shared<const Trajectory>(std::move(braked).value());
  plan.times_ms.topp = msSince(start_time);
  plan.times_ms.total = plan.times_ms.topp;
  return plan;
}

Result<Plan> MotionPlanner::plan(const PlanRequest& request) const {
  const auto start_time = std::chrono::steady_clock::now();
  const RobotModel& robot = model();
  if (auto refused = checkSceneAndOffset(robot, request)) return *refused;
  if (auto refused = checkJointCounts(robot, request, true)) return *refused;
  if (request.start_velocity.size() == 0) {
    PlanRequest at_rest = request;
    at_rest.start_velocity = JointVector::Zero(robot.jointCount());
    return plan(at_rest);
  }
  std::optional<PathPlanner> shifted;
  const Result<const PathPlanner*> found = pathsFor(robot, scenes_->path_planners, request, shifted);
  if (!found) return found.error();
  const PathPlanner& paths = *found.value();
  const bool moving = weightedNorm(request.start_velocity, robot.planner.metric) > 0.0;
  Result<Plan> chosen = inconsistentPlan();
  if (!moving) {
    chosen =
        timedPath(robot, paths, request.start, request.goal, request.pieces, JointVector::Zero(robot.jointCount()));
    if (!chosen && chosen.status() == PlanStatus::kStartInCollision) {
      chosen = escapeThenPlan(robot, paths, request, std::move(chosen));
    }
  } else {
    chosen = planMovingStart(MovingStartInputs{robot, paths, request}, movingStartStrategies());
  }
  if (!chosen) return chosen;
  Plan plan = std::move(chosen).value();
  plan.times_ms.grid = paths.gridBuildMs(request.pieces);
  plan.times_ms.total = msSince(start_time);
  return plan;
}

}  // namespace cyber::planner

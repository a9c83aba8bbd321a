#include "cyber/planner/motion_planner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "cyber/planner/clearance_escape.hpp"
#include "cyber/planner/fastest_stop.hpp"
#include "cyber/planner/joined_path.hpp"
#include "cyber/planner/path_timing.hpp"
#include "cyber/planner/trajectory_consistency.hpp"
#include "cyber/planner/weighted_norm.hpp"

namespace cyber::planner {
namespace {

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

Result<Plan> inconsistent() {
  return Result<Plan>::failure(
      PlanStatus::kSolverNotConverged,
      "the trajectory's velocities or accelerations do not integrate to its positions at 1 ms");
}

bool consistent(const MotionSettings& settings, const Trajectory& trajectory) {
  const ColumnConsistency c = columnConsistency(trajectory, settings.consistency_step_s);
  return c.position_error <= settings.max_position_error && c.velocity_error <= settings.max_velocity_error;
}

// A timed candidate with its columns' verdict, judged once. Candidates rank by agreeing columns
// first, then by duration.
struct Judged {
  Result<Plan> plan;
  bool consistent = false;
  [[nodiscard]] std::pair<int, double> rank() const {
    return {consistent ? 0 : 1, plan ? plan.value().trajectory->duration_s() : std::numeric_limits<double>::infinity()};
  }
};

Judged judged(const RobotModel& model, Result<Plan> plan) {
  const bool agrees = plan && consistent(model.planner.motion, *plan.value().trajectory);
  return {std::move(plan), agrees};
}

// A very short move from rest (tens of milliseconds) whose columns disagree at 1 ms: its switch
// from full acceleration to full braking is a large share of its peak speed, and the trapezoid
// across it errs by up to half the jump times the step (docs/moving-starts.md). Slowing it down
// uniformly moves the switch between the samples (by about half the added time), so the shortest
// slowdown that puts it where the columns agree, within the limits, is taken.
// The shortest uniform slowdown of `trajectory` by a multiple of MotionSettings::slower_step, up to `steps` of
// them, that stays within the limits and that `agrees` accepts.
template <class Agrees>
std::optional<Trajectory> shortestSlowdown(const RobotModel& model, const Trajectory& trajectory, int steps,
                                           Agrees&& agrees) {
  const MotionSettings& settings = model.planner.motion;
  const double duration = trajectory.duration_s();
  for (int i = 1; i <= steps && duration > 0.0; ++i) {
    Result<Trajectory> slower =
        slowedDown(trajectory, 1.0 + i * settings.slower_step * settings.consistency_step_s / duration);
    if (slower && agrees(slower.value()) && withinDriveLimits(slower.value(), model.planner.topp)) {
      return std::move(slower).value();
    }
  }
  return std::nullopt;
}

std::optional<Trajectory> consistentSlowdown(const RobotModel& model, const Trajectory& trajectory) {
  const MotionSettings& settings = model.planner.motion;
  if (trajectory.duration_s() > settings.slower_max_duration_s) return std::nullopt;
  return shortestSlowdown(model, trajectory, settings.slower_steps,
                          [&](const Trajectory& slower) { return consistent(settings, slower); });
}

// A move from rest whose columns still disagree: its early acceleration switch (a burst to a
// speed the voltage or a velocity cap holds) lands where the trapezoid across it errs, and a
// uniform slowdown hardly moves an early switch. The start made gentler by gentler_start_step at a
// time, up to gentler_start_steps, moves it (gentlerStart); the first whose columns agree within
// the limits (docs/moving-starts.md, "Consistent columns").
std::optional<Trajectory> consistentStart(const RobotModel& model, const Trajectory& trajectory) {
  const MotionSettings& settings = model.planner.motion;
  for (int i = 1; i <= settings.gentler_start_steps; ++i) {
    Result<Trajectory> gentler = gentlerStart(trajectory, 1.0 - i * settings.gentler_start_step);
    if (gentler && consistent(settings, gentler.value()) && withinDriveLimits(gentler.value(), model.planner.topp)) {
      return std::move(gentler).value();
    }
  }
  return std::nullopt;
}

// TOPP along the path stage's candidates from a start with velocity v0, in the order of their
// estimated time, until one gives a trajectory whose columns agree.
Result<Plan> timePaths(const RobotModel& model, const std::vector<PlannedPath>& found, const JointVector& v0) {
  // The spline leaves along v0 with unit speed in the metric Sigma, so sqrt(b_start) = |v0|_Sigma.
  const double speed = weightedNorm(v0, model.planner.metric);
  ToppSolver solver(model.planner.topp);
  Result<Plan> fallback = inconsistent();  // the first trajectory, when no candidate's columns agree
  bool have_fallback = false;
  double topp_ms = 0.0;
  for (size_t i = 0; i < found.size(); ++i) {
    const PlannedPath& path = found[i];
    const auto topp_start = std::chrono::steady_clock::now();
    Plan plan;
    Result<Trajectory> trajectory = solver.solve(path.path, model.driveModel(path.pieces), speed * speed, &plan.solver);
    topp_ms += msSince(topp_start);
    if (!trajectory) {
      if (i == 0) fallback = trajectory.error();
      continue;
    }
    bool agree = consistent(model.planner.motion, trajectory.value());
    plan.path_method = path.method;
    // From rest, slowing this path by at most two steps costs less than a slower path would.
    if (!agree && speed == 0.0) {
      if (std::optional<Trajectory> slower = consistentSlowdown(model, trajectory.value())) {
        trajectory = std::move(*slower);
        plan.path_method += ", slowed to agree at 1 ms";
        agree = true;
      } else if (std::optional<Trajectory> gentler = consistentStart(model, trajectory.value())) {
        trajectory = std::move(*gentler);
        plan.path_method += ", gentler start to agree at 1 ms";
        agree = true;
      }
    }
    plan.trajectory = std::make_shared<const Trajectory>(std::move(trajectory).value());
    plan.waypoints = path.waypoints;
    plan.min_clearance_m = path.min_clearance_m;
    plan.times_ms.search = path.search_ms;
    plan.times_ms.smooth = path.smooth_ms;
    plan.times_ms.topp = topp_ms;
    if (agree) return plan;
    if (!have_fallback) {
      fallback = std::move(plan);
      have_fallback = true;
    }
  }
  // None agrees (a moving start's are left to the candidate that stops first): the first.
  if (have_fallback) fallback.value().times_ms.topp = topp_ms;
  return fallback;
}

// The path stage from `start` leaving along v0, then timePaths.
Result<Plan> timedPath(const RobotModel& model, const PathPlanner& paths, const JointVector& start,
                       const JointVector& goal, HeldPieces pieces, const JointVector& v0,
                       PathAlternatives alternatives = PathAlternatives::kSearch) {
  Result<std::vector<PlannedPath>> found = paths.candidates(start, goal, pieces, v0, alternatives);
  if (!found) return found.error();
  return timePaths(model, found.value(), v0);
}

// The reachability pass's estimate of the first candidate's duration (path_timing.hpp), infinity
// when there is none.
double estimatedSeconds(const RobotModel& model, const Result<std::vector<PlannedPath>>& found, const JointVector& v0) {
  if (!found || found.value().empty()) return std::numeric_limits<double>::infinity();
  const double speed = weightedNorm(v0, model.planner.metric);
  return estimateDuration(*found.value().front().path, model.driveModel(found.value().front().pieces), speed * speed,
                          model.planner.motion.estimate_grid_points);
}

JointVector restOf(const Trajectory& stop) { return stop.path().at(stop.path().length()).q; }

// `first` (a stop, or a way out of the clearance, named by `what`), then the rest-to-rest plan
// `onward` from where it ends.
Result<Plan> joinAfter(const char* what, const PlanRequest& request, const Trajectory& first, Result<Plan> onward) {
  if (!onward) return onward;
  Result<Trajectory> joined = joinAtRest(first, *onward.value().trajectory);
  if (!joined) return joined.error();
  Plan plan = std::move(onward).value();
  plan.trajectory = std::make_shared<const Trajectory>(std::move(joined).value());
  plan.waypoints.insert(plan.waypoints.begin(), request.start);
  plan.path_method = fmt::format("{}, then {}", what, plan.path_method);
  return plan;
}

// The rest-to-rest plan from where `stop` ends, after it.
Result<Plan> planAfterStop(const RobotModel& model, const PathPlanner& paths, const PlanRequest& request,
                           const Trajectory& stop) {
  return joinAfter("stop", request, stop,
                   timedPath(model, paths, restOf(stop), request.goal, request.pieces, JointVector::Zero()));
}

// The candidate that is always there for a moving start (docs/moving-starts.md): the fastest
// stop along v0, then the rest-to-rest plan from where it stops. Its path stage comes first, so
// that both candidates' estimates decide which are timed (MotionPlanner::plan).
struct StopFirst {
  Result<Trajectory> stop = Result<Trajectory>::failure(PlanStatus::kInvalidInput, "no stop");
  Result<std::vector<PlannedPath>> onward =
      Result<std::vector<PlannedPath>>::failure(PlanStatus::kInvalidInput, "no stop");
  double stop_ms = 0.0;
  double estimate_s = std::numeric_limits<double>::infinity();  // stop + the onward estimate
  double onward_estimate_s = std::numeric_limits<double>::infinity();
};

StopFirst stopFirstPaths(const RobotModel& model, const PathPlanner& paths, const PlanRequest& request) {
  StopFirst out;
  const auto stop_start = std::chrono::steady_clock::now();
  ToppSolver solver(model.planner.topp);
  out.stop = fastestStop(model, paths.world(request.pieces), request.start, request.start_velocity, solver);
  out.stop_ms = msSince(stop_start);
  if (!out.stop) return out;
  out.onward = paths.candidates(restOf(out.stop.value()), request.goal, request.pieces);
  out.onward_estimate_s = estimatedSeconds(model, out.onward, JointVector::Zero());
  out.estimate_s = out.stop.value().duration_s() + out.onward_estimate_s;
  return out;
}

// The stop-first candidate timed. At the instant of rest the acceleration jumps (braking, then
// leaving along another direction); sampled every 1 ms, the columns then agree only when the jump
// falls near the middle between samples (the trapezoid of the two samples around it is then close
// to the true change of velocity), so when they do not, the stop is made gentle enough to move
// the junction later (docs/moving-starts.md).
Result<Plan> stopThenPlan(const RobotModel& model, const PathPlanner& paths, const PlanRequest& request,
                          const StopFirst& candidate) {
  if (!candidate.stop) return candidate.stop.error();
  if (!candidate.onward) return candidate.onward.error();
  const Trajectory& stop = candidate.stop.value();
  Result<Plan> plan = joinAfter("stop", request, stop, timePaths(model, candidate.onward.value(), JointVector::Zero()));
  const MotionSettings& settings = model.planner.motion;
  const double steps = stop.duration_s() / settings.consistency_step_s;
  // The later instants of rest in the middle half between two samples (where the trapezoid across
  // the jump errs by at most a quarter of it), earliest first.
  int tries = 0;
  for (int i = 1; i <= settings.gentler_steps && tries < settings.gentler_tries && plan &&
                  !consistent(settings, *plan.value().trajectory);
       ++i) {
    const double target = steps + settings.gentler_step * i;
    if (std::abs(target - std::floor(target) - 0.5) > 0.25) continue;
    ++tries;
    Result<Trajectory> gentler = stretchedStop(model, paths.world(request.pieces), stop, target / steps);
    plan = gentler ? planAfterStop(model, paths, request, gentler.value()) : gentler.error();
  }
  if (plan) plan.value().times_ms.topp += candidate.stop_ms;
  return plan;
}

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
                                 fmt::format("{}; {}", refused.error().reason, escape.error().reason));
  }
  const Result<Plan> onward =
      timedPath(model, paths, restOf(escape.value()), request.goal, request.pieces, JointVector::Zero());
  Result<Plan> plan = joinAfter("out of the clearance", request, escape.value(), onward);
  // The way out is a few millimetres, timed in tens of milliseconds: its switch from accelerating
  // to braking, and the jump at the junction, are large next to its peak speed, so its columns
  // may disagree at 1 ms as a short move's do. It is slowed as one is (consistentSlowdown), by
  // fractions of a step, until the joined columns agree.
  const MotionSettings& settings = model.planner.motion;
  if (plan && !consistent(settings, *plan.value().trajectory)) {
    Result<Plan> joined = plan;
    const auto joined_agrees = [&](const Trajectory& slower) {
      joined = joinAfter("out of the clearance", request, slower, onward);
      return joined && consistent(settings, *joined.value().trajectory);
    };
    if (shortestSlowdown(model, escape.value(), settings.escape_slower_steps, joined_agrees)) plan = std::move(joined);
  }
  if (plan) plan.value().min_clearance_m = std::min(plan.value().min_clearance_m, world.distance(request.start).value);
  return plan;
}

bool requestError(PlanStatus status) {
  return status == PlanStatus::kInvalidInput || status == PlanStatus::kStartOutOfRange ||
         status == PlanStatus::kGoalOutOfRange || status == PlanStatus::kStartInCollision ||
         status == PlanStatus::kGoalInCollision;
}

}  // namespace

Result<MotionPlanner> MotionPlanner::create(const RobotModel& model, const GridSelection& selection) {
  if (model.scenes.empty()) return Result<MotionPlanner>::failure(PlanStatus::kInvalidInput, "the robot has no scene");
  bool has_polygon = false;
  for (const LinkGeometry& link : model.links) has_polygon = has_polygon || !link.polygons.empty();
  if (!has_polygon) return Result<MotionPlanner>::failure(PlanStatus::kInvalidInput, "the robot has no link polygons");
  if (static_cast<int>(model.pieces.size()) > HeldPieces::kMaxPieces) {
    return Result<MotionPlanner>::failure(PlanStatus::kInvalidInput,
                                          fmt::format("at most {} game pieces", HeldPieces::kMaxPieces));
  }
  MotionPlanner planner;
  planner.model_ = model;
  planner.path_planners_.reserve(model.scenes.size());
  const double band_width = model.planner.search.offset_band_clearances * model.clearance_m;
  for (size_t index = 0; index < model.scenes.size(); ++index) {
    const Scene& scene = model.scenes[index];
    std::vector<PathPlanner>& bands = planner.path_planners_.emplace_back();
    if (selection.scene >= 0 && selection.scene != static_cast<int>(index)) continue;
    const bool moves = !scene.obstacles.empty();
    const std::optional<double>& only = selection.scene_offset_m;
    if (!only || *only == 0.0 || !moves) bands.emplace_back(model, scene);
    const JointRange& range = scene.offset_range_m;
    const double span = range.max - range.min;
    if (span <= 0.0 || !moves) continue;
    const int count = std::max(1, static_cast<int>(std::ceil(span / std::max(band_width, 1e-3))));
    for (int k = 0; k < count; ++k) {
      const JointRange band{range.min + span * k / count,
                            k + 1 == count ? range.max : range.min + span * (k + 1) / count};
      if (only && (*only == 0.0 || !band.contains(*only))) continue;
      bands.emplace_back(model, scene, band);
      if (only) break;
    }
  }
  return planner;
}

std::vector<JointRange> MotionPlanner::offsetBands(int scene) const {
  std::vector<JointRange> out;
  for (const PathPlanner& band : path_planners_[static_cast<size_t>(scene)]) out.push_back(band.band());
  return out;
}

Result<Plan> MotionPlanner::plan(const PlanRequest& request) const {
  const auto start_time = std::chrono::steady_clock::now();
  if (request.scene < 0 || request.scene >= static_cast<int>(path_planners_.size())) {
    return Result<Plan>::failure(PlanStatus::kInvalidInput, fmt::format("unknown scene index {}", request.scene));
  }
  if (!request.start_velocity.allFinite()) {
    return Result<Plan>::failure(PlanStatus::kInvalidInput, "start velocity is not finite");
  }
  // Offsets: the scene as drawn, or a band's grids with the worlds of the exact offset.
  const Scene& scene = model_.scenes[static_cast<size_t>(request.scene)];
  const double offset = request.scene_offset_m;
  if (!std::isfinite(offset) || !scene.offset_range_m.contains(offset, 1e-9)) {
    return Result<Plan>::failure(PlanStatus::kInvalidInput,
                                 fmt::format("scene offset {:.4f} m is outside scene {}'s range [{:.4f}, {:.4f}] m",
                                             offset, scene.name, scene.offset_range_m.min, scene.offset_range_m.max));
  }
  // The scene as drawn, or the band of grids that holds the offset with the exact offset's worlds.
  const std::vector<PathPlanner>& bands = path_planners_[static_cast<size_t>(request.scene)];
  const bool drawn = offset == 0.0 || scene.obstacles.empty();
  const auto base = std::find_if(bands.begin(), bands.end(), [&](const PathPlanner& p) {
    const JointRange& band = p.band();
    return drawn ? band.min == 0.0 && band.max == 0.0 : band.max > band.min && band.contains(offset, 1e-9);
  });
  if (base == bands.end()) {
    return Result<Plan>::failure(
        PlanStatus::kInvalidInput,
        fmt::format("this planner was built without the grids of scene {} at offset {:.4f} m", scene.name, offset));
  }
  std::optional<PathPlanner> shifted;
  if (!drawn) shifted = base->atOffset(offset);
  const PathPlanner& paths = shifted ? *shifted : *base;
  const bool moving = weightedNorm(request.start_velocity, model_.planner.metric) > 0.0;
  Result<Plan> chosen = inconsistent();
  if (!moving) {
    chosen = timedPath(model_, paths, request.start, request.goal, request.pieces, JointVector::Zero());
    if (!chosen && chosen.status() == PlanStatus::kStartInCollision) {
      chosen = escapeThenPlan(model_, paths, request, std::move(chosen));
    }
  } else {
    // Leaving along the velocity is timed on the search's path alone: the candidate that stops
    // first searches the alternatives (docs/moving-starts.md, "Planning time").
    Result<std::vector<PlannedPath>> direct_paths =
        paths.candidates(request.start, request.goal, request.pieces, request.start_velocity, PathAlternatives::kNone);
    // Errors of the request itself (bad poses, a goal in collision) are the same for both.
    if (!direct_paths && requestError(direct_paths.status())) return direct_paths.error();
    const StopFirst stop_first = stopFirstPaths(model_, paths, request);
    // Each candidate is timed only when its estimate leaves it a chance to win (docs/moving-starts.md).
    const double direct_estimate_s = estimatedSeconds(model_, direct_paths, request.start_velocity);
    const bool time_direct =
        direct_paths && model_.planner.motion.moving_estimate_low * direct_estimate_s <= stop_first.estimate_s;
    Judged direct = judged(model_, time_direct ? timePaths(model_, direct_paths.value(), request.start_velocity)
                                               : Result<Plan>(inconsistent()));
    const double stop_first_low_s = stop_first.stop
                                        ? stop_first.stop.value().duration_s() +
                                              model_.planner.motion.rest_estimate_low * stop_first.onward_estimate_s
                                        : 0.0;
    const bool direct_wins = direct.consistent && direct.plan.value().trajectory->duration_s() < stop_first_low_s;
    Judged stopped =
        judged(model_, direct_wins ? Result<Plan>(inconsistent()) : stopThenPlan(model_, paths, request, stop_first));
    if (!stopped.consistent && !time_direct && direct_paths) {
      direct = judged(model_, timePaths(model_, direct_paths.value(), request.start_velocity));
    }
    if (!direct.plan && !direct_paths) direct.plan = direct_paths.error();
    if (!direct.plan && !stopped.plan) {
      // Neither serves: say why stopping first did not either (a stop into an obstacle or a joint
      // limit, or no way on from where it stops), not only why leaving along the velocity failed.
      return Result<Plan>::failure(direct.plan.status(),
                                   direct.plan.error().reason + "; stopping first: " + stopped.plan.error().reason);
    }
    chosen = stopped.plan && (!direct.plan || stopped.rank() < direct.rank()) ? std::move(stopped.plan)
                                                                              : std::move(direct.plan);
  }
  if (!chosen) return chosen;
  Plan plan = std::move(chosen).value();
  plan.times_ms.grid = paths.gridBuildMs(request.pieces);
  plan.times_ms.total = msSince(start_time);
  return plan;
}

}  // namespace cyber::planner

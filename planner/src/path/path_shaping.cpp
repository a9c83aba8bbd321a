#include "path/path_shaping.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "math/weighted_norm.hpp"
#include "path/path_clearance.hpp"
#include "timing/path_timing.hpp"

namespace cyber::planner {
namespace {

// What both searches share: the knots' arc fractions along the starting polygon, the bumps over
// them, and one trial step from the best shape so far (kept when it is faster and clear).
class ShapeSearch {
 public:
  enum class Trial { kFaster, kNotFaster, kBlocked, kOutside };

  ShapeSearch(std::span<const JointVector> waypoints, int fixed_head, const JointVector& start_velocity,
              const CollisionWorld& world, const RobotModel& model, double b_start, int bumps, int grid_points)
      : world_(world),
        model_(model),
        drives_(model.driveModel(world.pieces())),
        start_velocity_(start_velocity),
        b_start_(b_start),
        bumps_(bumps),
        grid_points_(grid_points),
        free_first_(std::max(1, fixed_head)),
        free_last_(static_cast<int>(waypoints.size()) - 2) {
    best_.waypoints.assign(waypoints.begin(), waypoints.end());
    auto first = CubicSplinePath::through(best_.waypoints, model.planner.metric, start_velocity);
    if (!first.ok()) return;
    best_.path = std::move(first).value();
    best_.estimate_s = estimateDuration(best_.path, drives_, b_start, grid_points);
    best_.min_clearance_m = checkPath(best_.path, world, model, model.clearance_m).min_distance_m;
    u_.assign(waypoints.size(), 0.0);
    for (size_t k = 1; k < waypoints.size(); ++k)
      u_[k] = u_[k - 1] + weightedNorm(waypoints[k] - waypoints[k - 1], model.planner.metric);
    if (u_.empty() || !(u_.back() > 0.0)) return;
    for (double& x : u_) x /= u_.back();
    ready_ = free_last_ >= free_first_ && bumps > 0 && std::isfinite(best_.estimate_s);
  }

  [[nodiscard]] bool ready() const { return ready_; }
  [[nodiscard]] int parameters() const { return model_.jointCount() * bumps_; }
  [[nodiscard]] int evaluations() const { return best_.evaluations; }
  [[nodiscard]] int freeKnots() const { return free_last_ - free_first_ + 1; }

  // Moves every free knot's `joint` by amount * sin((m + 1) pi u), times a window that is zero at
  // the arc fraction pin_u and one from pin_width away (no window when pin_u < 0). kBlocked sets
  // blocked_at to the arc fraction where the clearance was lost.
  Trial tryStep(int parameter, double amount, double pin_u, double pin_width, double& blocked_at) {
    const int joint = parameter / bumps_, m = parameter % bumps_;
    trial_ = best_.waypoints;
    for (int k = free_first_; k <= free_last_; ++k) {
      const double x = u_[static_cast<size_t>(k)];
      double window = 1.0;
      if (pin_u >= 0.0) window = std::min(1.0, std::pow(std::abs(x - pin_u) / pin_width, 2));
      trial_[static_cast<size_t>(k)][joint] += amount * window * std::sin((m + 1) * std::numbers::pi * x);
      if (!model_.withinLimits(trial_[static_cast<size_t>(k)])) return Trial::kOutside;
    }
    ++best_.evaluations;
    auto spline = CubicSplinePath::through(trial_, model_.planner.metric, start_velocity_);
    if (!spline.ok()) return Trial::kNotFaster;
    const double estimate = estimateDuration(spline.value(), drives_, b_start_, grid_points_);
    if (!(estimate < best_.estimate_s * (1.0 - model_.planner.shape_search.min_gain))) return Trial::kNotFaster;
    const ClearanceCheck check = checkPath(spline.value(), world_, model_, model_.clearance_m);
    if (!check.ok()) {
      const double length = spline.value().length();
      if (!check.within_limits || !(length > 0.0)) return Trial::kOutside;
      blocked_at = check.at_s / length;
      return Trial::kBlocked;
    }
    best_.waypoints = trial_;
    best_.path = std::move(spline).value();
    best_.estimate_s = estimate;
    best_.min_clearance_m = check.min_distance_m;
    ++best_.improvements;
    return Trial::kFaster;
  }

  // The same over the whole path.
  Trial tryStep(int parameter, double amount) {
    double unused = 0.0;
    return tryStep(parameter, amount, -1.0, 1.0, unused);
  }

  ShapedPath take() { return std::move(best_); }

 private:
  const CollisionWorld& world_;
  const RobotModel& model_;
  DriveModel drives_;
  JointVector start_velocity_;
  double b_start_;
  int bumps_, grid_points_, free_first_, free_last_;
  bool ready_ = false;
  std::vector<double> u_;
  std::vector<JointVector> trial_;
  ShapedPath best_;
};

// Each joint's amplitude step in its own unit: the first joint's, then the later joints'.
JointVector initialSteps(const RobotModel& model, double first, double later) {
  JointVector out = JointVector::Constant(model.jointCount(), later);
  out[0] = first;
  return out;
}

}  // namespace

ShapedPath shapeForTime(std::span<const JointVector> waypoints, int fixed_head, const JointVector& start_velocity,
                        const CollisionWorld& world, const RobotModel& model, double b_start,
                        const ShapeSearchSettings& settings) {
  ShapeSearch search(waypoints, fixed_head, start_velocity, world, model, b_start, settings.bumps,
                     settings.grid_points);
  if (!search.ready()) return search.take();
  const int bumps = settings.bumps;
  const JointVector initial_step = initialSteps(model, settings.initial_step_first, settings.initial_step_later);
  JointVector step = initial_step;
  const JointVector min_step = settings.min_step_fraction * initial_step;
  std::vector<int> last_sign(static_cast<size_t>(search.parameters()), 1);
  while (search.evaluations() < settings.max_evaluations && (step.array() >= min_step.array()).any()) {
    bool improved = false;
    for (int p = 0; p < search.parameters() && search.evaluations() < settings.max_evaluations; ++p) {
      // The direction that helped last time first.
      for (int sign : {last_sign[static_cast<size_t>(p)], -last_sign[static_cast<size_t>(p)]}) {
        if (search.evaluations() >= settings.max_evaluations) break;
        if (search.tryStep(p, sign * step[p / bumps]) != ShapeSearch::Trial::kFaster) continue;
        last_sign[static_cast<size_t>(p)] = sign;
        improved = true;
        break;
      }
    }
    if (!improved) step *= 0.5;
  }
  return search.take();
}

ShapedPath refineShapeForTime(std::span<const JointVector> waypoints, int fixed_head, const JointVector& start_velocity,
                              const CollisionWorld& world, const RobotModel& model, double b_start,
                              const ShapeRefinementSettings& settings) {
  ShapeSearch search(waypoints, fixed_head, start_velocity, world, model, b_start, settings.bumps,
                     settings.grid_points);
  if (!search.ready() || search.freeKnots() < 2 * settings.bumps) return search.take();
  const auto parameters = static_cast<size_t>(search.parameters());
  const JointVector initial_step = initialSteps(model, settings.initial_step_first, settings.initial_step_later);
  std::vector<double> scale(parameters, 1.0);  // of the initial step, per amplitude
  std::vector<int> last_sign(parameters, 1);
  auto live = [&] {
    return std::any_of(scale.begin(), scale.end(), [&](double f) { return f >= settings.min_step_fraction; });
  };
  while (search.evaluations() < settings.max_evaluations && live()) {
    for (size_t p = 0; p < parameters && search.evaluations() < settings.max_evaluations; ++p) {
      if (scale[p] < settings.min_step_fraction) continue;
      const double amount = scale[p] * initial_step[static_cast<int>(p) / settings.bumps];
      bool helped = false;
      for (int sign : {last_sign[p], -last_sign[p]}) {
        double blocked_at = -1.0;
        ShapeSearch::Trial trial = ShapeSearch::Trial::kOutside;
        if (search.evaluations() < settings.max_evaluations)
          trial = search.tryStep(static_cast<int>(p), sign * amount, -1.0, 1.0, blocked_at);
        // A faster shape that loses the clearance somewhere is tried once more held still there:
        // a path that touches the clearance at one place can still be faster elsewhere.
        if (trial == ShapeSearch::Trial::kBlocked && settings.pin_width > 0.0 &&
            search.evaluations() < settings.max_evaluations)
          trial = search.tryStep(static_cast<int>(p), sign * amount, blocked_at, settings.pin_width, blocked_at);
        if (trial != ShapeSearch::Trial::kFaster) continue;
        last_sign[p] = sign;
        helped = true;
        break;
      }
      scale[p] = helped ? std::min(settings.max_step_fraction, 2.0 * scale[p]) : 0.5 * scale[p];
    }
  }
  return search.take();
}

}  // namespace cyber::planner

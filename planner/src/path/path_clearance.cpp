#include "path/path_clearance.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace cyber::planner {
namespace {

// A distance this far past the cutoff [m] still counts as beyond it: the roundoff of the bound.
constexpr double kCutoffSlackM = 1e-9;
// Speeds and Lipschitz bounds are at least this, so a path at rest does not divide by zero.
constexpr double kNegligibleRate = 1e-12;

// Walks a curve q(u), u in [u0, u1], whose joint speeds are bounded by abs_speed per unit u.
// Returns false at the first sample with d < clearance.
template <class Curve>
bool walk(const Curve& curve, double u0, double u1, const JointVector& abs_speed, const CollisionWorld& world,
          double clearance_m, double max_step, ClearanceCheck* check, bool* have_exact) {
  const double lipschitz = world.lipschitzBound(abs_speed);  // |dd/du| <= lipschitz
  const double fastest = abs_speed.maxCoeff();
  const double dense_du = fastest > 0.0 ? max_step / fastest : std::numeric_limits<double>::infinity();
  // Distances beyond what the rest of the curve could lose need not be exact.
  const double cutoff = clearance_m + lipschitz * (u1 - u0) + kCutoffSlackM;
  double u = u0;
  for (;;) {
    const SignedDistance d = world.distance(curve(u), cutoff);
    ++check->evaluations;
    // Values beyond the cutoff are only lower bounds; the minimum reported is the smallest exact
    // value when there is one.
    const bool smaller =
        d.exact ? (!*have_exact || d.value < check->min_distance_m) : (!*have_exact && d.value < check->min_distance_m);
    if (smaller) {
      check->min_distance_m = d.value;
      check->at_s = u;
      *have_exact = *have_exact || d.exact;
    }
    if (d.value < clearance_m) {
      check->clear = false;
      return false;
    }
    if (u >= u1) return true;
    const double certified_du =
        lipschitz > 0.0 ? (d.value - clearance_m) / lipschitz : std::numeric_limits<double>::infinity();
    u = std::min(u1, u + std::max(dense_du, certified_du));
  }
}

}  // namespace

ClearanceCheck checkSegment(const CollisionWorld& world, const JointVector& a, const JointVector& b, double clearance_m,
                            double max_step) {
  ClearanceCheck check;
  bool have_exact = false;
  const JointVector delta = b - a;
  walk([&](double u) -> JointVector { return a + u * delta; }, 0.0, 1.0, delta.cwiseAbs(), world, clearance_m, max_step,
       &check, &have_exact);
  return check;
}

StepCheck checkStep(const CollisionWorld& world, const JointVector& a, const JointVector& b, double clearance_m,
                    double distance_a_m, double distance_b_m, double max_step) {
  StepCheck check;
  const JointVector delta = b - a;
  const double lipschitz = world.lipschitzBound(delta.cwiseAbs());  // |dd/du| <= lipschitz
  const double fastest = delta.cwiseAbs().maxCoeff();
  const double dense_du = fastest > 0.0 ? max_step / fastest : 1.0;
  struct Part {
    double u0, u1, d0, d1;
  };
  // Halving from [0, 1] to dense_du >= max_step / fastest takes far fewer levels than this.
  constexpr int kMaxDepth = 64;
  std::array<Part, 2 * kMaxDepth> parts{};
  int count = 0;
  parts[static_cast<size_t>(count++)] = {0.0, 1.0, distance_a_m, distance_b_m};
  while (count > 0) {
    const Part part = parts[static_cast<size_t>(--count)];
    const double width = part.u1 - part.u0;
    if (endsClearStep(part.d0, part.d1, lipschitz * width, clearance_m)) continue;
    if (width <= dense_du || count + 2 > static_cast<int>(parts.size())) continue;
    const double u = 0.5 * (part.u0 + part.u1);
    // A distance past this clears both halves whatever it is, so it need not be exact.
    const double d = world.distance(a + u * delta, clearance_m + 0.5 * lipschitz * width + kCutoffSlackM).value;
    ++check.evaluations;
    if (d < clearance_m) {
      check.clear = false;
      return check;
    }
    parts[static_cast<size_t>(count++)] = {u, part.u1, d, part.d1};
    parts[static_cast<size_t>(count++)] = {part.u0, u, part.d0, d};
  }
  return check;
}

ClearanceCheck checkPath(const CubicSplinePath& path, const CollisionWorld& world, const RobotModel& model,
                         double clearance_m, double max_step) {
  ClearanceCheck check;
  bool have_exact = false;
  auto q_at = [&](double s) -> JointVector { return path.at(s).q; };
  if (path.segmentCount() == 0) {
    walk(q_at, 0.0, 0.0, JointVector::Zero(model.jointCount()), world, clearance_m, max_step, &check, &have_exact);
    check.within_limits = model.withinLimits(path.at(0.0).q);
    return check;
  }
  const auto& knots = path.knots();
  for (int k = 0; k < path.segmentCount(); ++k) {
    const CubicSplinePath::SegmentBounds bounds = path.segmentBounds(k);
    if (!model.withinLimits(bounds.q_min) || !model.withinLimits(bounds.q_max)) {
      check.within_limits = false;
      check.at_s = knots[static_cast<size_t>(k)];
      return check;
    }
    if (!walk(q_at, knots[static_cast<size_t>(k)], knots[static_cast<size_t>(k) + 1], bounds.abs_dq_max, world,
              clearance_m, max_step, &check, &have_exact)) {
      return check;
    }
  }
  // Certified steps can be long where the margin is large; refine the reported minimum with a
  // dense scan of exact distances around the closest sample.
  check.min_distance_m = world.distance(path.at(check.at_s).q).value;
  const double s_min = check.at_s;
  const int k = std::clamp(static_cast<int>(std::upper_bound(knots.begin(), knots.end(), s_min) - knots.begin()) - 1, 0,
                           path.segmentCount() - 1);
  const JointVector speed = path.segmentBounds(k).abs_dq_max;
  const double ds = max_step / std::max(speed.maxCoeff(), kNegligibleRate);
  const double lipschitz = std::max(world.lipschitzBound(speed), kNegligibleRate);
  const double radius = std::min(ds + (check.min_distance_m - clearance_m) / lipschitz, path.length());
  const int samples = std::min(100, static_cast<int>(std::ceil(radius / ds)));
  for (int i = -samples; i <= samples; ++i) {
    const double s = std::clamp(s_min + radius * i / std::max(samples, 1), 0.0, path.length());
    const double d = world.distance(path.at(s).q).value;
    ++check.evaluations;
    if (d < check.min_distance_m) {
      check.min_distance_m = d;
      check.at_s = s;
    }
  }
  if (check.min_distance_m < clearance_m) check.clear = false;
  return check;
}

}  // namespace cyber::planner

#include "path/synchronised_path.hpp"

#include <algorithm>
#include <cmath>

#include "path/joined_path.hpp"
#include "path/path_clearance.hpp"
#include "timing/path_timing.hpp"

namespace cyber::planner {

namespace {

// One joint's own rest-to-rest profile: the fraction of its travel reached at each time.
struct JointProfile {
  TimedFractions times;
  [[nodiscard]] double durationS() const { return times.time_s.back(); }
  // The fraction reached t seconds after the start (0 before, 1 after the end).
  [[nodiscard]] double at(double t) const {
    const std::vector<double>& ts = times.time_s;
    if (t <= 0.0) return 0.0;
    if (t >= ts.back()) return 1.0;
    const auto i = static_cast<size_t>(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin());
    const double u = (t - ts[i - 1]) / (ts[i] - ts[i - 1]);
    return times.fraction[i - 1] + u * (times.fraction[i] - times.fraction[i - 1]);
  }
};

std::optional<JointProfile> ownProfile(const JointVector& from, const JointVector& to, int joint,
                                       const DriveModel& drives, int grid_points) {
  JointVector direction = JointVector::Zero(from.size());
  const double travel = std::abs(to[joint] - from[joint]);
  direction[joint] = to[joint] > from[joint] ? 1.0 : -1.0;
  JointProfile profile{reachabilityTimes(StraightPath(from, direction, travel), drives, 0.0, grid_points)};
  if (profile.times.time_s.size() < 2 || !(profile.durationS() > 0.0)) return std::nullopt;
  return profile;
}

}  // namespace

std::optional<SynchronisedPath> synchronisedPath(const JointVector& from, const JointVector& to,
                                                 const CollisionWorld& world, const RobotModel& model, double beat_s,
                                                 const SynchronisedSettings& settings) {
  const DriveModel drives = model.driveModel(world.pieces());
  // StraightPath's length is in joint units here, so each joint's travel must be worth planning.
  constexpr double kMinTravel = 1e-3;  // m or rad
  const int joints = model.jointCount();
  // One joint alone has nothing to synchronise with.
  if (joints < 2) return std::nullopt;
  for (int j = 0; j < joints; ++j) {
    if (!(std::abs(to[j] - from[j]) > kMinTravel)) return std::nullopt;
  }
  PerJoint<std::optional<JointProfile>> own(joints);
  int slow = 0;
  for (int j = 0; j < joints; ++j) {
    own[j] = ownProfile(from, to, j, drives, settings.profile_points);
    if (!own[j]) return std::nullopt;
    if (own[j]->durationS() > own[slow]->durationS()) slow = j;
  }
  const JointProfile& slower = *own[slow];
  if (!(slower.durationS() < beat_s)) return std::nullopt;

  std::optional<SynchronisedPath> best;
  int estimates = 0;
  std::vector<JointVector> waypoints(static_cast<size_t>(settings.samples) + 1, from);
  const int n = settings.divisions;
  for (double slowdown : settings.slowdowns) {
    const double total_s = slowdown * slower.durationS();
    if (!(total_s < beat_s) || (best && best->estimate_s <= total_s)) break;
    for (int d = 0; d <= n; ++d) {
      for (int w = 0; w <= n; ++w) {
        for (int k = 0; k <= settings.samples; ++k) {
          const double t = total_s * k / settings.samples;
          JointVector& q = waypoints[static_cast<size_t>(k)];
          q[slow] = from[slow] + (to[slow] - from[slow]) * slower.at(t / slowdown);
          for (int fast = 0; fast < joints; ++fast) {
            if (fast == slow) continue;
            // A faster joint's motion lasts from its own duration to the whole move, and starts
            // anywhere that lets it end in time (the same shares of both for every faster joint).
            const JointProfile& faster = *own[fast];
            const double stretch_s = faster.durationS() + (total_s - faster.durationS()) * d / n;
            const double delay_s = (total_s - stretch_s) * w / n;
            q[fast] = from[fast] + (to[fast] - from[fast]) * faster.at((t - delay_s) * faster.durationS() / stretch_s);
          }
        }
        waypoints.back() = to;  // exactly: the fractions' last product may miss it by a rounding
        auto spline = CubicSplinePath::through(waypoints, model.planner.metric);
        if (!spline.ok()) continue;
        const ClearanceCheck check = checkPath(spline.value(), world, model, model.clearance_m);
        if (!check.ok()) continue;
        const double estimate = estimateDuration(spline.value(), drives, 0.0, settings.estimate_points);
        ++estimates;
        if (std::isfinite(estimate) && (!best || estimate < best->estimate_s)) {
          best = SynchronisedPath{waypoints, std::move(spline).value(), estimate, slower.durationS(),
                                  check.min_distance_m};
        }
        if (estimates >= settings.max_estimates || (best && best->estimate_s <= settings.accept_ratio * total_s)) {
          return best;
        }
      }
    }
  }
  return best;
}

}  // namespace cyber::planner

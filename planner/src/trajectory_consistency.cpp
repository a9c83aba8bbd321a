#include "cyber/planner/trajectory_consistency.hpp"

#include <algorithm>
#include <cmath>

namespace cyber::planner {
namespace {

// Below these a joint's travel or speed is noise, not a scale (m or rad, and per second).
constexpr double kTravelFloor = 1e-4;
constexpr double kSpeedFloor = 1e-3;

}  // namespace

ColumnConsistency columnConsistency(const Trajectory& trajectory, double step_s) {
  const double duration = trajectory.duration_s();
  const long steps = static_cast<long>(std::floor(duration / step_s + 1e-9));
  const bool tail = duration - static_cast<double>(steps) * step_s > 1e-9;
  const long count = steps + 1 + (tail ? 1 : 0);
  auto time_of = [&](long i) { return i > steps ? duration : static_cast<double>(i) * step_s; };

  // First pass: each joint's scale; second: the integrals against it.
  JointVector low = trajectory.sample(0.0).q, high = low, peak = JointVector::Zero();
  for (long i = 0; i < count; ++i) {
    const TrajectorySample s = trajectory.sample(time_of(i));
    low = low.cwiseMin(s.q);
    high = high.cwiseMax(s.q);
    peak = peak.cwiseMax(s.qdot.cwiseAbs());
  }
  const JointVector travel = (high - low).cwiseMax(JointVector::Constant(kTravelFloor));
  const JointVector speed = peak.cwiseMax(JointVector::Constant(kSpeedFloor));

  ColumnConsistency out;
  TrajectorySample previous = trajectory.sample(0.0);
  const TrajectorySample first = previous;
  JointVector integral_q = JointVector::Zero(), integral_v = JointVector::Zero();
  for (long i = 1; i < count; ++i) {
    const TrajectorySample s = trajectory.sample(time_of(i));
    const double h = s.t - previous.t;
    integral_q += 0.5 * h * (s.qdot + previous.qdot);
    integral_v += 0.5 * h * (s.qddot + previous.qddot);
    for (int j = 0; j < kJointCount; ++j) {
      out.position_error = std::max(out.position_error, std::abs(s.q[j] - first.q[j] - integral_q[j]) / travel[j]);
      out.velocity_error = std::max(out.velocity_error, std::abs(s.qdot[j] - first.qdot[j] - integral_v[j]) / speed[j]);
    }
    previous = s;
  }
  return out;
}

}  // namespace cyber::planner

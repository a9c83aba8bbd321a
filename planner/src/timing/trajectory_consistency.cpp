#include "cyber/planner/trajectory.hpp"

#include <algorithm>
#include <cmath>

#include "math/roundoff.hpp"

namespace cyber::planner {
namespace {

// Below these a joint's travel or speed is noise, not a scale (m or rad, and per second).
constexpr double kTravelFloor = 1e-4;
constexpr double kSpeedFloor = 1e-3;
// A duration within this of a whole number of steps [s] ends on a step: no extra sample for the
// roundoff of the division.
constexpr double kTailRoundoffS = 1e-9;

}  // namespace

ColumnConsistency columnConsistency(const Trajectory& trajectory, double step_s) {
  const double duration = trajectory.duration_s();
  const long steps = static_cast<long>(std::floor(duration / step_s + kWholeCountSlack));
  const bool tail = duration - static_cast<double>(steps) * step_s > kTailRoundoffS;
  const long count = steps + 1 + (tail ? 1 : 0);
  auto time_of = [&](long i) { return i > steps ? duration : static_cast<double>(i) * step_s; };

  // One pass: the largest raw errors, then each joint's scale (travel and peak speed over the
  // same samples) divides them, as the scale is the same for every sample.
  TrajectorySample previous = trajectory.sampleMotion(0.0);
  const TrajectorySample first = previous;
  JointVector low = first.q, high = first.q, peak = first.qdot.cwiseAbs();
  JointVector integral_q = JointVector::Zero(first.q.size()), integral_v = JointVector::Zero(first.q.size());
  JointVector position_error = JointVector::Zero(first.q.size()), velocity_error = JointVector::Zero(first.q.size());
  for (long i = 1; i < count; ++i) {
    const TrajectorySample s = trajectory.sampleMotion(time_of(i));
    low = low.cwiseMin(s.q);
    high = high.cwiseMax(s.q);
    peak = peak.cwiseMax(s.qdot.cwiseAbs());
    const double h = s.t - previous.t;
    integral_q += 0.5 * h * (s.qdot + previous.qdot);
    integral_v += 0.5 * h * (s.qddot + previous.qddot);
    position_error = position_error.cwiseMax((s.q - first.q - integral_q).cwiseAbs());
    velocity_error = velocity_error.cwiseMax((s.qdot - first.qdot - integral_v).cwiseAbs());
    previous = s;
  }
  const JointVector travel = (high - low).cwiseMax(JointVector::Constant(first.q.size(), kTravelFloor));
  const JointVector speed = peak.cwiseMax(JointVector::Constant(first.q.size(), kSpeedFloor));
  ColumnConsistency out;
  out.position_error = position_error.cwiseQuotient(travel).maxCoeff();
  out.velocity_error = velocity_error.cwiseQuotient(speed).maxCoeff();
  return out;
}

}  // namespace cyber::planner

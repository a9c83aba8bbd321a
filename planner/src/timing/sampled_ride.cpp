#include "cyber/planner/trajectory.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "math/roundoff.hpp"

namespace cyber::planner {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// b is the square of the speed relative to the trajectory's own: 1e4 is a hundred times faster,
// far beyond any ride a drive limit admits where the path moves.
constexpr double kLargestB = 1e4;
// b = 4: the trajectory's own speed doubled, a second sample beside b = 1 that separates the
// terms in b from those in sqrt(b).
constexpr double kDoubledSpeedB = 4.0;
// Coefficients and slacks (volts per unit of a, and b) below this are roundoff of a zero.
constexpr double kNegligible = 1e-12;
// 60 halvings of [0, kLargestB] reach the precision of a double.
constexpr int kBisections = 60;

// One joint at one sample, its voltage at path acceleration a and path speed squared b (b > 0):
// V = alpha a + beta b + gamma sqrt(b) + offset + kS sgn(q'), read off DriveModel::volts.
struct JointRow {
  double dq = 0.0;   // q'(s): the trajectory's velocity
  double d2q = 0.0;  // q''(s): its acceleration
  double alpha = 0.0, beta = 0.0, gamma = 0.0, offset = 0.0, coulomb = 0.0;
};

using Row = PerJoint<JointRow>;

Row rowAt(const DriveModel& drives, const TrajectorySample& s) {
  // V(a, b) is linear in a (q'' = q' a + q'' b) and, for b > 0, beta b + gamma sqrt(b) plus
  // constants (the Coriolis terms go with b, the back-EMF and kV with sqrt(b)): evaluations at rest,
  // at a = 1 and at a = 0 with b = 1 and 4 separate them once kS sgn(q') is taken out.
  const JointVector zero = JointVector::Zero(drives.jointCount());
  const JointVector at_rest = drives.volts(s.q, zero, zero);
  const JointVector per_a = drives.volts(s.q, zero, s.qdot) - at_rest;
  const JointVector b1 = drives.volts(s.q, s.qdot, s.qddot) - at_rest;
  const JointVector b4 = drives.volts(s.q, 2.0 * s.qdot, kDoubledSpeedB * s.qddot) - at_rest;
  Row row(drives.jointCount());
  for (int j = 0; j < row.size(); ++j) {
    JointRow& r = row[j];
    r.dq = s.qdot[j];
    r.d2q = s.qddot[j];
    r.coulomb = drives.drive(j).kS_volts * static_cast<double>((r.dq > 0.0) - (r.dq < 0.0));
    r.alpha = per_a[j];
    r.offset = at_rest[j];
    r.beta = 0.5 * ((b4[j] - r.coulomb) - 2.0 * (b1[j] - r.coulomb));
    r.gamma = (b1[j] - r.coulomb) - r.beta;
  }
  return row;
}

struct Interval {
  double lo = -kInfinity;
  double hi = kInfinity;
  [[nodiscard]] bool empty() const { return lo > hi; }
  // |c0 + c1 a| <= limit.
  void bound(double c0, double c1, double limit) {
    if (std::abs(c1) < kNegligible) {
      if (std::abs(c0) > limit) {
        lo = kInfinity;
        hi = -kInfinity;
      }
      return;
    }
    const double a1 = (-limit - c0) / c1;
    const double a2 = (limit - c0) / c1;
    lo = std::max(lo, std::min(a1, a2));
    hi = std::min(hi, std::max(a1, a2));
  }
};

// The path accelerations every drive limit admits at one sample and path speed squared b.
Interval admissible(const DriveModel& drives, const Row& row, double b) {
  Interval interval;
  const double speed = std::sqrt(b);
  for (int j = 0; j < row.size() && !interval.empty(); ++j) {
    const JointRow& r = row[j];
    const DriveParams& d = drives.drive(j);
    const double qdot = r.dq * speed;
    const double volts0 = r.beta * b + r.gamma * speed + r.offset + (b > 0.0 ? r.coulomb : 0.0);
    interval.bound(volts0, r.alpha, d.voltage_limit_volts);
    const double amps0 = d.amps(volts0, qdot);
    interval.bound(amps0, d.amps(volts0 + r.alpha, qdot) - amps0, d.current_limit_amps);
    if (d.velocity_limit) interval.bound(qdot, 0.0, *d.velocity_limit);
    if (d.acceleration_limit) interval.bound(r.d2q * b, r.dq, *d.acceleration_limit);
  }
  return interval;
}

// The largest b in [0, ceiling] with accept(b), given accept(0) and that accept holds below any b
// it holds at.
template <class Accept>
double largestAccepted(double ceiling, Accept&& accept) {
  if (accept(ceiling)) return ceiling;
  double lo = 0.0, hi = ceiling;
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    (accept(mid) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

std::optional<double> fastestRideAlongSamples(const Trajectory& trajectory, std::span<const double> times_s) {
  if (times_s.size() < 2) return std::nullopt;
  const size_t intervals = times_s.size() - 1;
  const DriveModel& drives = trajectory.drives();
  std::vector<Row> rows(times_s.size());
  for (size_t k = 0; k <= intervals; ++k) rows[k] = rowAt(drives, trajectory.sampleMotion(times_s[k]));
  const auto ds = [&](size_t k) { return times_s[k + 1] - times_s[k]; };

  // Backward pass: the largest b at each sample from which the rest of the path can still be
  // ridden to rest, braking at the lower bound of each interval.
  std::vector<double> controllable(intervals + 1);
  for (size_t k = intervals + 1; k-- > 0;) {
    const bool last = k == intervals;
    const auto accept = [&](double b) {
      const Interval interval = admissible(drives, rows[k], b);
      return !interval.empty() && (last || b + 2.0 * interval.lo * ds(k) <= controllable[k + 1] + kNegligible);
    };
    if (!accept(0.0)) return std::nullopt;
    controllable[k] = largestAccepted(kLargestB, accept);
  }

  // Forward pass: accelerate at the upper bound, never above what can still be braked.
  const bool moving_start = !trajectory.sampleMotion(0.0).qdot.isZero();
  double b = moving_start ? std::min(1.0, controllable[0]) : controllable[0];
  double time_s = 0.0;
  for (size_t k = 0; k < intervals; ++k) {
    const Interval interval = admissible(drives, rows[k], b);
    const double next = std::max(0.0, std::min(controllable[k + 1], b + 2.0 * interval.hi * ds(k)));
    const double speeds = std::sqrt(b) + std::sqrt(next);
    if (speeds <= 0.0) return std::nullopt;
    time_s += 2.0 * ds(k) / speeds;
    b = next;
  }
  return time_s;
}

std::optional<double> fastestRideAlongPath(const Trajectory& trajectory, double step_s) {
  const double duration = trajectory.duration_s();
  const auto intervals = static_cast<size_t>(std::max(1.0, std::ceil(duration / step_s - kWholeCountSlack)));
  std::vector<double> times_s(intervals + 1);
  for (size_t k = 0; k <= intervals; ++k)
    times_s[k] = std::min(duration, duration * static_cast<double>(k) / static_cast<double>(intervals));
  return fastestRideAlongSamples(trajectory, times_s);
}

}  // namespace cyber::planner

#include "path/cubic_spline_path.hpp"
#include "math/weighted_norm.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cyber::planner {
namespace {

// Waypoints closer than this (weighted) are one knot: a zero-length segment has no direction.
constexpr double kMergeDistance = 1e-9;
// The cubic's degree and its second derivative's factor: (u^3)' = 3 u^2, (u^3)'' = 6 u; the 3 of
// the continuity and natural-end conditions below comes from the same derivative.
constexpr double kCubicDegree = 3.0;
constexpr double kCubicSecond = 6.0;
// A leading coefficient this small is a polynomial of lower degree: dividing by it would overflow.
constexpr double kNegligibleCoefficient = 1e-300;

// The segments' lengths h_k (in knot units) and slopes delta_k = (p_{k+1} - p_k) / h_k.
struct Chords {
  std::vector<double> h;
  std::vector<JointVector> delta;
};

Chords chordsOf(const std::vector<double>& knots, const std::vector<JointVector>& points) {
  const size_t n = points.size() - 1;
  Chords c{std::vector<double>(n), std::vector<JointVector>(n)};
  for (size_t k = 0; k < n; ++k) {
    c.h[k] = knots[k + 1] - knots[k];
    c.delta[k] = (points[k + 1] - points[k]) / c.h[k];
  }
  return c;
}

// The knot derivatives m_k, from a tridiagonal system (both joints share the matrix):
//   interior: m_{k-1}/h_{k-1} + 2 (1/h_{k-1} + 1/h_k) m_k + m_{k+1}/h_k
//             = 3 (delta_{k-1}/h_{k-1} + delta_k/h_k)        (q'' continuous at knot k)
//   natural end: 2 m_0 + m_1 = 3 delta_0,   m_{n-1} + 2 m_n = 3 delta_{n-1}
//   clamped start: m_0 = v0 / |v0|_Sigma
// Apart from through() so that the solve reads on its own.
std::vector<JointVector> knotDerivatives(const Chords& chords, const JointVector& metric,
                                         const JointVector& start_direction) {
  const std::vector<double>& h = chords.h;
  const std::vector<JointVector>& delta = chords.delta;
  const size_t n = h.size();
  const size_t size = n + 1;
  std::vector<double> lower(size, 0.0), diag(size, 0.0), upper(size, 0.0);
  std::vector<JointVector> rhs(size, JointVector::Zero(metric.size()));
  const double start_speed = weightedNorm(start_direction, metric);
  if (start_speed > 0.0) {
    diag[0] = 1.0;
    rhs[0] = start_direction / start_speed;
  } else {
    diag[0] = 2.0;
    upper[0] = 1.0;
    rhs[0] = kCubicDegree * delta[0];
  }
  for (size_t k = 1; k < n; ++k) {
    lower[k] = 1.0 / h[k - 1];
    upper[k] = 1.0 / h[k];
    diag[k] = 2.0 * (lower[k] + upper[k]);
    rhs[k] = kCubicDegree * (delta[k - 1] / h[k - 1] + delta[k] / h[k]);
  }
  lower[size - 1] = 1.0;
  diag[size - 1] = 2.0;
  rhs[size - 1] = kCubicDegree * delta[size - 2];
  // Thomas algorithm; the matrix is strictly diagonally dominant in every row but a clamped first.
  for (size_t k = 1; k < size; ++k) {
    const double factor = lower[k] / diag[k - 1];
    diag[k] -= factor * upper[k - 1];
    rhs[k] -= factor * rhs[k - 1];
  }
  std::vector<JointVector> m(size);
  m[size - 1] = rhs[size - 1] / diag[size - 1];
  for (size_t k = size - 1; k-- > 0;) m[k] = (rhs[k] - upper[k] * m[k + 1]) / diag[k];
  return m;
}

}  // namespace

Result<CubicSplinePath> CubicSplinePath::through(std::span<const JointVector> waypoints, const JointVector& metric,
                                                 const JointVector& start_direction) {
  if (waypoints.empty()) return Result<CubicSplinePath>::failure(PlanStatus::kInvalidInput, "spline needs a waypoint");
  if (!metric.allFinite() || metric.minCoeff() <= 0.0) {
    return Result<CubicSplinePath>::failure(PlanStatus::kInvalidInput, "metric must be positive and finite");
  }
  if (!start_direction.allFinite()) {
    return Result<CubicSplinePath>::failure(PlanStatus::kInvalidInput, "start direction must be finite");
  }
  for (const JointVector& p : waypoints) {
    if (!p.allFinite()) return Result<CubicSplinePath>::failure(PlanStatus::kInvalidInput, "waypoints must be finite");
  }

  CubicSplinePath path;
  path.points_.push_back(waypoints.front());
  path.knots_.push_back(0.0);
  for (size_t k = 1; k < waypoints.size(); ++k) {
    const double chord = weightedNorm(waypoints[k] - path.points_.back(), metric);
    if (chord < kMergeDistance) {
      // Keep the goal exact; a merged inner point is simply dropped.
      if (k + 1 == waypoints.size() && path.points_.size() > 1) path.points_.back() = waypoints[k];
      continue;
    }
    path.points_.push_back(waypoints[k]);
    path.knots_.push_back(path.knots_.back() + chord);
  }
  // Re-measure the knots: replacing the last point changed the last chord.
  for (size_t k = 1; k < path.points_.size(); ++k) {
    path.knots_[k] = path.knots_[k - 1] + weightedNorm(path.points_[k] - path.points_[k - 1], metric);
  }
  const int n = static_cast<int>(path.points_.size()) - 1;  // segments
  if (n == 0) return path;

  const Chords chords = chordsOf(path.knots_, path.points_);
  const std::vector<double>& h = chords.h;
  const std::vector<JointVector>& delta = chords.delta;
  const std::vector<JointVector> m = knotDerivatives(chords, metric, start_direction);
  path.segments_.reserve(static_cast<size_t>(n));
  for (size_t k = 0; k < static_cast<size_t>(n); ++k) {
    Segment seg;
    seg.c0 = path.points_[k];
    seg.c1 = m[k];
    seg.c2 = (kCubicDegree * delta[k] - 2.0 * m[k] - m[k + 1]) / h[k];
    seg.c3 = (m[k] + m[k + 1] - 2.0 * delta[k]) / (h[k] * h[k]);
    path.segments_.push_back(seg);
  }
  return path;
}

int CubicSplinePath::segmentOf(double s) const {
  // The last knot <= s, kept inside [0, n-1] so s = length() evaluates the last segment's end.
  const auto it = std::upper_bound(knots_.begin(), knots_.end(), s);
  const auto k = static_cast<int>(it - knots_.begin()) - 1;
  return std::clamp(k, 0, segmentCount() - 1);
}

PathPoint CubicSplinePath::at(double s) const {
  PathPoint p;
  if (segments_.empty()) {
    if (!points_.empty()) p.q = points_.front();
    p.dq_ds = JointVector::Zero(p.q.size());
    p.d2q_ds2 = JointVector::Zero(p.q.size());
    return p;
  }
  s = std::clamp(s, 0.0, length());
  const int k = segmentOf(s);
  const Segment& seg = segments_[static_cast<size_t>(k)];
  const double u = s - knots_[static_cast<size_t>(k)];
  // The polynomial reproduces its start point exactly (u = 0) but its end point only to rounding:
  // a goal on a joint limit would come out a few ulp outside. The end knot is returned exactly.
  p.q = s == knots_[static_cast<size_t>(k) + 1] ? points_[static_cast<size_t>(k) + 1]
                                                : JointVector(seg.c0 + u * (seg.c1 + u * (seg.c2 + u * seg.c3)));
  p.dq_ds = seg.c1 + u * (2.0 * seg.c2 + u * kCubicDegree * seg.c3);
  p.d2q_ds2 = 2.0 * seg.c2 + u * kCubicSecond * seg.c3;
  return p;
}

CubicSplinePath::SegmentBounds CubicSplinePath::segmentBounds(int segment) const {
  SegmentBounds b;
  const Segment& seg = segments_[static_cast<size_t>(segment)];
  const double h = knots_[static_cast<size_t>(segment) + 1] - knots_[static_cast<size_t>(segment)];
  const int joints = static_cast<int>(seg.c0.size());
  b.q_min.resize(joints);
  b.q_max.resize(joints);
  b.abs_dq_max.resize(joints);
  for (int j = 0; j < joints; ++j) {
    const double c0 = seg.c0[j], c1 = seg.c1[j], c2 = seg.c2[j], c3 = seg.c3[j];
    auto q = [&](double u) { return c0 + u * (c1 + u * (c2 + u * c3)); };
    auto dq = [&](double u) { return c1 + u * (2.0 * c2 + u * kCubicDegree * c3); };
    // The end values are the knots themselves, exactly: q(h) evaluated carries rounding, which
    // would put a segment ending on a joint limit a few ulp outside it.
    const double q_end = points_[static_cast<size_t>(segment) + 1][j];
    double lo = std::min(c0, q_end), hi = std::max(c0, q_end);
    double speed = std::max(std::abs(dq(0.0)), std::abs(dq(h)));
    // Interior extrema of q: roots of q' = 3 c3 u^2 + 2 c2 u + c1.
    double roots[2];
    int root_count = 0;
    if (std::abs(c3) > kNegligibleCoefficient) {
      const double disc = c2 * c2 - kCubicDegree * c3 * c1;
      if (disc >= 0.0) {
        const double r = std::sqrt(disc);
        roots[root_count++] = (-c2 + r) / (kCubicDegree * c3);
        roots[root_count++] = (-c2 - r) / (kCubicDegree * c3);
      }
      // Extremum of q' at its vertex.
      const double vertex = -c2 / (kCubicDegree * c3);
      if (vertex > 0.0 && vertex < h) speed = std::max(speed, std::abs(dq(vertex)));
    } else if (std::abs(c2) > kNegligibleCoefficient) {
      roots[root_count++] = -c1 / (2.0 * c2);
    }
    for (int r = 0; r < root_count; ++r) {
      if (roots[r] > 0.0 && roots[r] < h) {
        lo = std::min(lo, q(roots[r]));
        hi = std::max(hi, q(roots[r]));
      }
    }
    b.q_min[j] = lo;
    b.q_max[j] = hi;
    b.abs_dq_max[j] = speed;
  }
  return b;
}

}  // namespace cyber::planner

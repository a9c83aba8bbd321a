#pragma once
// The C^2 cubic spline through waypoints of algorithm.md section 2.4: one cubic per joint and
// segment, parameterised by the cumulative weighted chord length s (|dq|_Sigma), knot derivatives
// from the tridiagonal system of the report's eqs. 1-5.
//
// End conditions: natural (q'' = 0) at the goal; at the start natural too, or clamped to a given
// direction scaled to unit speed in the Sigma metric (so that a TOPP starting with
// sqrt(b) = |v0|_Sigma reproduces the velocity v0).

#include <span>
#include <vector>

#include "cyber/planner/types.hpp"

namespace cyber::planner {

class CubicSplinePath final : public GeometricPath {
 public:
  // Per joint over one segment: range of q and the largest |q'|.
  struct SegmentBounds {
    JointVector q_min;
    JointVector q_max;
    JointVector abs_dq_max;
  };

  CubicSplinePath() = default;

  // Consecutive waypoints closer than 1e-9 (weighted) are merged (the last waypoint is kept
  // exactly). One remaining point gives the zero-length path. A non-zero start_direction clamps
  // q'(0) = start_direction / |start_direction|_Sigma.
  static Result<CubicSplinePath> through(std::span<const JointVector> waypoints, const JointVector& metric,
                                         const JointVector& start_direction = {});

  [[nodiscard]] double length() const override { return knots_.empty() ? 0.0 : knots_.back(); }
  [[nodiscard]] PathPoint at(double s) const override;

  [[nodiscard]] int segmentCount() const { return static_cast<int>(segments_.size()); }
  [[nodiscard]] const std::vector<double>& knots() const { return knots_; }
  [[nodiscard]] const std::vector<JointVector>& points() const { return points_; }
  [[nodiscard]] SegmentBounds segmentBounds(int segment) const;

 private:
  struct Segment {  // q(u) = c0 + c1 u + c2 u^2 + c3 u^3, u = s - knot
    JointVector c0, c1, c2, c3;
  };
  [[nodiscard]] int segmentOf(double s) const;

  std::vector<double> knots_;
  std::vector<JointVector> points_;
  std::vector<Segment> segments_;
};

}  // namespace cyber::planner

#pragma once
// Paths built from pieces for the "stop first" candidate of a moving start (docs/moving-starts.md):
// a straight piece along the start velocity, then the rest-to-rest path from where it stops.

#include <memory>

#include "cyber/planner/trajectory.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

// q(s) = from + s * direction, s in [0, length]; direction has unit Sigma-norm, so a start
// velocity v0 along it has path speed^2 b = |v0|_Sigma^2.
class StraightPath final : public GeometricPath {
 public:
  StraightPath(const JointVector& from, const JointVector& direction, double length)
      : from_(from), direction_(direction), length_(length) {}
  [[nodiscard]] double length() const override { return length_; }
  [[nodiscard]] PathPoint at(double s) const override;

 private:
  JointVector from_;
  JointVector direction_;
  double length_;
};

// first, then second from where first ends (the caller makes them meet). At the junction the
// second piece answers: a trajectory through it is at rest there and leaves along the second.
class JoinedPath final : public GeometricPath {
 public:
  JoinedPath(std::shared_ptr<const GeometricPath> first, std::shared_ptr<const GeometricPath> second)
      : first_(std::move(first)), second_(std::move(second)) {}
  [[nodiscard]] double length() const override { return first_->length() + second_->length(); }
  [[nodiscard]] PathPoint at(double s) const override;

 private:
  std::shared_ptr<const GeometricPath> first_;
  std::shared_ptr<const GeometricPath> second_;
};

// `first` ends at rest where `second` starts at rest: one trajectory over their JoinedPath,
// stopped for an instant at the junction. kInvalidInput when either is not at rest there.
Result<Trajectory> joinAtRest(const Trajectory& first, const Trajectory& second);

}  // namespace cyber::planner

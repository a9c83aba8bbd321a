#pragma once
// A geometric path q(s), s in [0, length]: what the path stage produces and TOPP consumes.
// s is the weighted arc length of algorithm.md section 2.4 for splines; TOPP only needs q, q', q''.

#include "cyber/planner/types.hpp"

namespace cyber::planner {

struct PathPoint {
  JointVector q = JointVector::Zero();
  JointVector dq_ds = JointVector::Zero();    // q'(s)
  JointVector d2q_ds2 = JointVector::Zero();  // q''(s)
};

class GeometricPath {
 public:
  virtual ~GeometricPath() = default;
  [[nodiscard]] virtual double length() const = 0;
  // s is clamped to [0, length()]. Must not allocate (the streamer samples through it).
  [[nodiscard]] virtual PathPoint at(double s) const = 0;
};

}  // namespace cyber::planner

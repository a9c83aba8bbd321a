#pragma once
// The pose of the arm for a joint vector q = (t, theta) (algorithm.md section 1):
// world = pivot(t) + R(theta) p, pivot(t) = rail.base_m + t (cos tilt, sin tilt).

#include <cmath>

#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

// (x, y) -> (-y, x): rotation by +90 degrees, the derivative of R(theta) p with respect to theta.
inline Point2 perpendicular(const Point2& v) { return Point2(-v.y(), v.x()); }

struct ArmPose {
  Point2 pivot = Point2::Zero();
  Point2 rail_direction = Point2(1.0, 0.0);  // d pivot / dt (unit)
  double cos_theta = 1.0;
  double sin_theta = 0.0;

  [[nodiscard]] Point2 rotate(const Point2& p) const {
    return Point2(cos_theta * p.x() - sin_theta * p.y(), sin_theta * p.x() + cos_theta * p.y());
  }
  [[nodiscard]] Point2 toWorld(const Point2& p_arm) const { return pivot + rotate(p_arm); }

  // Velocity of the arm-fixed point currently at world position x, per unit joint rate:
  // column 0 is d x / dt, column 1 is d x / dtheta.
  [[nodiscard]] Eigen::Matrix2d pointJacobian(const Point2& x_world) const {
    Eigen::Matrix2d jacobian;
    jacobian.col(0) = rail_direction;
    jacobian.col(1) = perpendicular(x_world - pivot);
    return jacobian;
  }
};

inline Point2 railDirection(const Rail& rail) { return Point2(std::cos(rail.tilt_rad), std::sin(rail.tilt_rad)); }

// rail_direction = railDirection(rail), passed in so hot loops do not recompute it.
inline ArmPose armPose(const Point2& rail_base_m, const Point2& rail_direction, const JointVector& q) {
  ArmPose pose;
  pose.rail_direction = rail_direction;
  pose.pivot = rail_base_m + q[kElevator] * rail_direction;
  pose.cos_theta = std::cos(q[kArm]);
  pose.sin_theta = std::sin(q[kArm]);
  return pose;
}

inline ArmPose armPose(const Rail& rail, const JointVector& q) { return armPose(rail.base_m, railDirection(rail), q); }

}  // namespace cyber::planner

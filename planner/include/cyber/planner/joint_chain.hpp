#pragma once
// A serial chain of two joints in the 2-D side view (docs/algorithm.md section 1): the frame of
// link k is its parent's frame (the world's for link 0) moved by Trans(origin_m) and then by the
// joint: a revolute joint turns it by axis_rad + q (q in rad); a prismatic joint slides it by
// q (cos axis_rad, sin axis_rad) without turning it (q in m). So a prismatic joint's carriage keeps the
// world's orientation and an arm on it measures its angle from +x; a double-jointed arm's elbow
// angle is relative to the shoulder link; a telescope with axis 0 slides along its pivot link.

#include <array>
#include <cmath>
#include <string>

#include <Eigen/Core>

#include "cyber/planner/types.hpp"

namespace cyber::planner {

enum class JointType { kPrismatic, kRevolute };

struct JointRange {
  double min = 0.0;
  double max = 0.0;
  [[nodiscard]] bool contains(double x, double tolerance = 0.0) const {
    return x >= min - tolerance && x <= max + tolerance;
  }
};

// The unit of a joint's value: "m" (prismatic) or "rad" (revolute).
inline const char* unitName(JointType type) { return type == JointType::kPrismatic ? "m" : "rad"; }

struct ChainJoint {
  std::string name;
  JointType type = JointType::kRevolute;
  Point2 origin_m = Point2::Zero();  // in the parent frame
  double axis_rad = 0.0;             // in the parent frame
  JointRange range;                  // m (prismatic) or rad (revolute)
};

using JointChain = std::array<ChainJoint, kJointCount>;

// A rigid frame in the world: x_world = origin_m + R(angle) x_link.
struct LinkFrame {
  Point2 origin_m = Point2::Zero();
  double cos_angle = 1.0;
  double sin_angle = 0.0;

  [[nodiscard]] Point2 rotate(const Point2& p) const {
    return Point2(cos_angle * p.x() - sin_angle * p.y(), sin_angle * p.x() + cos_angle * p.y());
  }
  [[nodiscard]] Point2 toWorld(const Point2& p_link) const { return origin_m + rotate(p_link); }
  [[nodiscard]] double angle_rad() const { return std::atan2(sin_angle, cos_angle); }
};

// The frame of a joint's link for joint value q, given its parent's frame.
inline LinkFrame childFrame(const LinkFrame& parent, const ChainJoint& joint, double q) {
  LinkFrame frame;
  frame.origin_m = parent.toWorld(joint.origin_m);
  const double c = std::cos(joint.axis_rad);
  const double s = std::sin(joint.axis_rad);
  // Axis direction in the world: the parent's rotation applied to (cos axis, sin axis).
  const double axis_c = parent.cos_angle * c - parent.sin_angle * s;
  const double axis_s = parent.sin_angle * c + parent.cos_angle * s;
  if (joint.type == JointType::kPrismatic) {
    frame.origin_m += q * Point2(axis_c, axis_s);
    frame.cos_angle = parent.cos_angle;
    frame.sin_angle = parent.sin_angle;
  } else {
    const double cq = std::cos(q);
    const double sq = std::sin(q);
    frame.cos_angle = axis_c * cq - axis_s * sq;
    frame.sin_angle = axis_s * cq + axis_c * sq;
  }
  return frame;
}

// Both links' frames at q (index = joint index).
inline std::array<LinkFrame, kJointCount> linkFrames(const JointChain& chain, const JointVector& q) {
  const LinkFrame first = childFrame(LinkFrame{}, chain[0], q[0]);
  return {first, childFrame(first, chain[1], q[1])};
}

// (x, y) -> (-y, x): rotation by +90 degrees, the derivative of R(angle) p with respect to angle.
inline Point2 perpendicular(const Point2& v) { return Point2(-v.y(), v.x()); }

// Both links' frames at one q, with what the point Jacobians need.
struct ChainPose {
  std::array<LinkFrame, kJointCount> frames;
  std::array<JointType, kJointCount> types{JointType::kRevolute, JointType::kRevolute};
  std::array<Point2, kJointCount> travel;  // a prismatic joint's direction of travel in the world

  // Velocity of the point of link `link` now at world position x per unit joint rate: column j
  // is dx/dq_j (zero for joints after the link; a revolute joint turns x about its origin, a
  // prismatic one moves it along its travel).
  [[nodiscard]] Eigen::Matrix2d pointJacobian(int link, const Point2& x_world) const {
    Eigen::Matrix2d jacobian = Eigen::Matrix2d::Zero();
    for (int j = 0; j <= link; ++j) {
      jacobian.col(j) = types[static_cast<size_t>(j)] == JointType::kRevolute
                            ? perpendicular(x_world - frames[static_cast<size_t>(j)].origin_m)
                            : travel[static_cast<size_t>(j)];
    }
    return jacobian;
  }
};

inline ChainPose chainPose(const JointChain& chain, const JointVector& q) {
  ChainPose pose;
  LinkFrame parent;
  for (int j = 0; j < kJointCount; ++j) {
    const ChainJoint& joint = chain[static_cast<size_t>(j)];
    pose.types[static_cast<size_t>(j)] = joint.type;
    pose.travel[static_cast<size_t>(j)] = parent.rotate(Point2(std::cos(joint.axis_rad), std::sin(joint.axis_rad)));
    parent = childFrame(parent, joint, q[j]);
    pose.frames[static_cast<size_t>(j)] = parent;
  }
  return pose;
}

}  // namespace cyber::planner

#pragma once
// A serial chain of one to three joints in the 2-D side view (docs/algorithm.md section 1): the frame of
// link k is its parent's frame (the world's for link 0) moved by Trans(origin_m) and then by the
// joint: a revolute joint turns it by axis_rad + q (q in rad); a prismatic joint slides it by
// q (cos axis_rad, sin axis_rad) without turning it (q in m). So a prismatic joint's carriage keeps the
// world's orientation and an arm on it measures its angle from +x; a double-jointed arm's elbow
// angle is relative to the shoulder link; a telescope with axis 0 slides along its pivot link.

#include <array>
#include <cmath>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "cyber/planner/types.hpp"

namespace cyber::planner {

/// How a joint moves its link: sliding along its axis (m) or turning about it (rad).
enum class JointType { kPrismatic, kRevolute };

/// The closed interval of a joint's values (m or rad), or of a scene's offsets (m).
struct JointRange {
  double min = 0.0;
  double max = 0.0;
  [[nodiscard]] bool contains(double x, double tolerance = 0.0) const {
    return x >= min - tolerance && x <= max + tolerance;
  }
};

/// The unit of a joint's value: "m" (prismatic) or "rad" (revolute).
inline const char* unitName(JointType type) { return type == JointType::kPrismatic ? "m" : "rad"; }

/// One joint of the chain: its type, where it sits in its parent's frame, and its range.
struct ChainJoint {
  std::string name;
  JointType type = JointType::kRevolute;
  Point2 origin_m = Point2::Zero();  ///< in the parent frame
  double axis_rad = 0.0;             ///< in the parent frame
  JointRange range;                  ///< m (prismatic) or rad (revolute)
};

/// The joints in chain order, each carried by the one before it (1 to kMaxJoints).
using JointChain = PerJoint<ChainJoint>;

/// A rigid frame in the world: x_world = origin_m + R(angle) x_link.
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

/// The frame of a joint's link for joint value q, given its parent's frame.
inline LinkFrame childFrame(const LinkFrame& parent, const ChainJoint& joint, double q) {
  LinkFrame frame;
  frame.origin_m = parent.toWorld(joint.origin_m);
  const double c = std::cos(joint.axis_rad);
  const double s = std::sin(joint.axis_rad);
  /// Axis direction in the world: the parent's rotation applied to (cos axis, sin axis).
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

/// Every link's frame at q (index = joint index).
inline PerJoint<LinkFrame> linkFrames(const JointChain& chain, const JointVector& q) {
  PerJoint<LinkFrame> frames;
  LinkFrame parent;
  for (int j = 0; j < chain.size(); ++j) {
    parent = childFrame(parent, chain[j], q[j]);
    frames.push_back(parent);
  }
  return frames;
}

/// (x, y) -> (-y, x): rotation by +90 degrees, the derivative of R(angle) p with respect to angle.
inline Point2 perpendicular(const Point2& v) { return Point2(-v.y(), v.x()); }

/// Every link's frame at one q, with what the point Jacobians need.
struct ChainPose {
  PerJoint<LinkFrame> frames;
  PerJoint<JointType> types;
  PerJoint<Point2> travel;  ///< a prismatic joint's direction of travel in the world

  /// Velocity of the point of link `link` now at world position x per unit joint rate: column j
  /// is dx/dq_j (zero for joints after the link; a revolute joint turns x about its origin, a
  /// prismatic one moves it along its travel).
  [[nodiscard]] PointJacobian pointJacobian(int link, const Point2& x_world) const {
    PointJacobian jacobian = PointJacobian::Zero(2, frames.size());
    for (int j = 0; j <= link; ++j) {
      jacobian.col(j) = types[j] == JointType::kRevolute ? perpendicular(x_world - frames[j].origin_m) : travel[j];
    }
    return jacobian;
  }
};

/// The frames of every link of the chain at joint values q.
inline ChainPose chainPose(const JointChain& chain, const JointVector& q) {
  ChainPose pose;
  LinkFrame parent;
  for (int j = 0; j < chain.size(); ++j) {
    const ChainJoint& joint = chain[j];
    pose.types.push_back(joint.type);
    pose.travel.push_back(parent.rotate(Point2(std::cos(joint.axis_rad), std::sin(joint.axis_rad))));
    parent = childFrame(parent, joint, q[j]);
    pose.frames.push_back(parent);
  }
  return pose;
}

/// A DC motor as WPILib's DCMotor describes it (docs/algorithm.md section 3): V = I R + omega / Kv,
/// torque = Kt I.

/// DC motor figures as WPILib's DCMotor gives them.
struct MotorParams {
  double nominal_voltage_volts = 12.0;
  double stall_torque_nm = 0.0;
  double stall_current_amps = 0.0;
  double free_current_amps = 0.0;
  double free_speed_radps = 0.0;

  [[nodiscard]] double resistanceOhms() const { return nominal_voltage_volts / stall_current_amps; }
  /// Kv in rad/s per volt of back-EMF.
  [[nodiscard]] double kvRadpsPerVolt() const {
    return free_speed_radps / (nominal_voltage_volts - resistanceOhms() * free_current_amps);
  }
  [[nodiscard]] double ktNmPerAmp() const { return stall_torque_nm / stall_current_amps; }
};

/// Coupled rigid-body dynamics of a serial chain of one to three joints (docs/algorithm.md section 3,
/// "Coupled rigid-body dynamics"): tau = M(q) qdd + c(q, qd) + g(q) for any pair of prismatic and
/// revolute joints, its form along a path q(s) (linear in the path acceleration a and the path
/// speed squared b), and the voltage and current of the motors that drive it.
///
/// Pure and allocation-free: fixed-size Eigen values, no I/O; the TOPP evaluates it per grid point.

inline constexpr double kStandardGravityMps2 = 9.80665;

/// Mass data of everything that moves with one link's frame.
struct LinkInertia {
  double mass_kg = 0.0;
  Point2 cg_m = Point2::Zero();  ///< centre of mass in the link frame
  double moi_kgm2 = 0.0;         ///< moment of inertia about the centre of mass
};

/// The one body that two bodies fixed in the same link frame make (parallel-axis theorem): how a
/// held piece adds to its link. Two massless bodies give a massless one at the origin.
[[nodiscard]] LinkInertia combine(const LinkInertia& a, const LinkInertia& b);

/// The motors of one joint under the rigid-body model: `motor_count` identical motors, all at the
/// same voltage, geared by `gearing` (motor rad per joint rad or per metre). Limits are per motor.
struct RigidBodyDrive {
  MotorParams motor;
  int motor_count = 1;
  double gearing = 1.0;
  double kS_volts = 0.0;
  double voltage_limit_volts = 12.0;
  double current_limit_amps = 0.0;

  /// R / (Kt G n): volts per N m of joint torque (N of force for a prismatic joint).
  [[nodiscard]] double voltsPerLoad() const;
  /// G / Kv: back-EMF volts per joint rad/s (m/s).
  [[nodiscard]] double backEmfVoltsPerRate() const;
  /// V = kS sgn(qdot) + tau R / (Kt G n) + G qdot / Kv for joint torque (force) `load`.
  [[nodiscard]] double volts(double load, double qdot) const;
  /// Current of each motor, I = (V - G qdot / Kv) / R.
  [[nodiscard]] double amps(double volts, double qdot) const;
};

/// Joint torques (forces) along a path: tau = alpha a + beta b + gravity, with a = s-ddot and
/// b = s-dot^2.
struct PathTorque {
  JointVector alpha;    ///< M q'
  JointVector beta;     ///< M q'' + c(q, q')
  JointVector gravity;  ///< g(q)

  [[nodiscard]] JointVector at(double a, double b) const { return alpha * a + beta * b + gravity; }
};

/// One joint's motor voltage along a path, kS aside:
///   V = alpha a + beta b + gamma sqrt(b) + offset + kS sgn(qdot),
/// and its current times R is the same without the gamma term (the back-EMF). The Coulomb term is
/// left to the caller, whose sign rule depends on the interval (topp_problem.hpp).
struct PathVoltage {
  double alpha = 0.0;   ///< volts per unit of a
  double beta = 0.0;    ///< volts per unit of b
  double gamma = 0.0;   ///< G q' / Kv: volts per unit of sqrt(b)
  double offset = 0.0;  ///< the gravity term in volts
};

/// Joint `joint`'s PathVoltage from the chain's PathTorque and the path tangent q'.
[[nodiscard]] PathVoltage pathVoltage(const RigidBodyDrive& drive, const PathTorque& torque, const JointVector& dq_ds,
                                      int joint);

/// The chain, its links' bodies (index = joint index) and gravity g acting in -y.
class ChainDynamics {
 public:
  ChainDynamics(const JointChain& chain, const PerJoint<LinkInertia>& bodies,
                double gravity_mps2 = kStandardGravityMps2);

  [[nodiscard]] int jointCount() const { return chain_.size(); }
  [[nodiscard]] JointMatrix massMatrix(const JointVector& q) const;
  /// c(q, qdot): the Coriolis and centripetal terms, quadratic in qdot.
  [[nodiscard]] JointVector velocityTerms(const JointVector& q, const JointVector& qdot) const;
  [[nodiscard]] JointVector gravityTerms(const JointVector& q) const;
  [[nodiscard]] JointVector torque(const JointVector& q, const JointVector& qdot, const JointVector& qddot) const;
  /// Along q(s): tau = M q' a + (M q'' + c(q, q')) b + g(q), since c(q, q' sdot) = c(q, q') b.
  [[nodiscard]] PathTorque alongPath(const JointVector& q, const JointVector& dq_ds, const JointVector& d2q_ds2) const;

  [[nodiscard]] const PerJoint<LinkInertia>& bodies() const { return bodies_; }

 private:
  /// Positions and Jacobians of the chain at one q.
  struct Kinematics {
    PerJoint<Point2> cg_m;                   ///< each body's centre of mass, world
    PerJoint<PointJacobian> cg_jacobian;     ///< d cg_k / dq
    PerJoint<Point2> pivot_m;                ///< each joint's origin (a revolute joint's centre of rotation)
    PerJoint<PointJacobian> pivot_jacobian;  ///< d pivot_k / dq (it moves with the links before k)
    PerJoint<Point2> travel;                 ///< each prismatic joint's unit direction
  };

  [[nodiscard]] Kinematics kinematics(const JointVector& q) const;
  [[nodiscard]] JointMatrix massMatrix(const Kinematics& k) const;
  [[nodiscard]] JointVector velocityTerms(const Kinematics& k, const JointVector& qdot) const;
  [[nodiscard]] JointVector gravityTerms(const Kinematics& k) const;

  JointChain chain_;  ///< names dropped: copies never allocate
  PerJoint<LinkInertia> bodies_;
  /// Row k: d(angle of link k)/dq, constant for a planar chain (1 for each revolute joint <= k).
  PerJoint<JointRow> angle_jacobian_;
  double gravity_mps2_;
};

/// The voltage each joint's motors need for a motion, and the current they draw (docs/algorithm.md
/// section 3): what the TOPP's rows, the trajectory's samples and the limit checks evaluate.

/// f(psi) of the WPILib feedforward's gravity term, psi the joint's absolute angle in the world
/// (RobotModel::gravityAngle): 1, cos psi, sin psi or 0.
enum class GravityModel { kConstant, kCosine, kSine, kNone };

/// One joint's drive: WPILib feedforward, the motors behind it and its limits.
/// Joint units are m (prismatic) or rad (revolute); kV is V per unit/s, kA V per unit/s^2.
struct DriveParams {
  MotorParams motor;
  int motor_count = 1;
  double gearing = 1.0;  ///< motor rad per joint unit
  double kS_volts = 0.0;
  double kG_volts = 0.0;
  double kV = 0.0;
  double kA = 0.0;
  GravityModel gravity = GravityModel::kConstant;
  double voltage_limit_volts = 12.0;
  double current_limit_amps = 0.0;           ///< per motor
  std::optional<double> velocity_limit;      ///< joint units/s
  std::optional<double> acceleration_limit;  ///< joint units/s^2

  [[nodiscard]] double gravityFactor(double psi_rad) const;  ///< f(psi) of algorithm.md section 3
  /// Feedforward voltage V(psi, qdot, qddot) and the per-motor current it draws.
  [[nodiscard]] double volts(double psi_rad, double qdot, double qddot) const;
  [[nodiscard]] double amps(double volts, double qdot) const;
};

/// How the joints' voltages follow from their motion (docs/algorithm.md section 3): each joint's
/// WPILib feedforward on its own, or the coupled rigid-body dynamics of the chain.
enum class DriveKind { kFeedforward, kRigidBody };

/// Every joint's drive with what its voltage needs of the chain (no names: copying it allocates
/// nothing). Along a path a joint's voltage is alpha a + beta b + gamma sqrt(b) + offset +
/// kS sgn(qdot) for either kind (PathVoltage, chain.hpp); its current times R is the same
/// with gamma less the back-EMF's G q' / Kv.
class DriveModel {
 public:
  DriveModel() = default;
  /// WPILib feedforward per joint.
  DriveModel(const JointChain& chain, const PerJoint<DriveParams>& drives);
  /// Coupled rigid-body dynamics: the drives' motors, gearing, kS and limits (their kG, kV, kA are
  /// not used) driving `dynamics`.
  DriveModel(const PerJoint<DriveParams>& drives, const ChainDynamics& dynamics);

  [[nodiscard]] DriveKind kind() const { return dynamics_ ? DriveKind::kRigidBody : DriveKind::kFeedforward; }

  [[nodiscard]] int jointCount() const { return drives_.size(); }
  [[nodiscard]] const DriveParams& drive(int joint) const { return drives_[joint]; }
  [[nodiscard]] const PerJoint<DriveParams>& drives() const { return drives_; }

  /// psi_j(q): the absolute angle in the world of joint j's gravity term: a revolute joint's link
  /// x axis, a prismatic joint's direction of travel.
  [[nodiscard]] double gravityAngle(int joint, const JointVector& q) const;
  [[nodiscard]] JointVector volts(const JointVector& q, const JointVector& qdot, const JointVector& qddot) const;
  [[nodiscard]] JointVector amps(const JointVector& volts, const JointVector& qdot) const;
  /// Every joint's path coefficients at one path point.
  [[nodiscard]] PerJoint<PathVoltage> pathVoltages(const PathPoint& p) const;

 private:
  [[nodiscard]] RigidBodyDrive rigidBodyDrive(int joint) const;

  PerJoint<DriveParams> drives_;
  std::optional<ChainDynamics> dynamics_;
  PerJoint<JointType> types_;
  PerJoint<double> axes_rad_;
};

}  // namespace cyber::planner

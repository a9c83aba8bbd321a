#pragma once
// Coupled rigid-body dynamics of a two-joint serial chain (docs/algorithm.md section 3,
// "Coupled rigid-body dynamics"): tau = M(q) qdd + c(q, qd) + g(q) for any pair of prismatic and
// revolute joints, its form along a path q(s) (linear in the path acceleration a and the path
// speed squared b), and the voltage and current of the motors that drive it.
//
// Pure and allocation-free: fixed-size Eigen values, no I/O; the TOPP evaluates it per grid point.

#include <array>

#include <Eigen/Core>

#include "cyber/planner/joint_chain.hpp"
#include "cyber/planner/motor_params.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

inline constexpr double kStandardGravityMps2 = 9.80665;

// Mass data of everything that moves with one link's frame.
struct LinkInertia {
  double mass_kg = 0.0;
  Point2 cg_m = Point2::Zero();  // centre of mass in the link frame
  double moi_kgm2 = 0.0;         // moment of inertia about the centre of mass
};

// The one body that two bodies fixed in the same link frame make (parallel-axis theorem): how a
// held piece adds to its link. Two massless bodies give a massless one at the origin.
[[nodiscard]] LinkInertia combine(const LinkInertia& a, const LinkInertia& b);

// The motors of one joint under the rigid-body model: `motor_count` identical motors, all at the
// same voltage, geared by `gearing` (motor rad per joint rad or per metre). Limits are per motor.
struct RigidBodyDrive {
  MotorParams motor;
  int motor_count = 1;
  double gearing = 1.0;
  double kS_volts = 0.0;
  double voltage_limit_volts = 12.0;
  double current_limit_amps = 0.0;

  // R / (Kt G n): volts per N m of joint torque (N of force for a prismatic joint).
  [[nodiscard]] double voltsPerLoad() const;
  // G / Kv: back-EMF volts per joint rad/s (m/s).
  [[nodiscard]] double backEmfVoltsPerRate() const;
  // V = kS sgn(qdot) + tau R / (Kt G n) + G qdot / Kv for joint torque (force) `load`.
  [[nodiscard]] double volts(double load, double qdot) const;
  // Current of each motor, I = (V - G qdot / Kv) / R.
  [[nodiscard]] double amps(double volts, double qdot) const;
};

// Joint torques (forces) along a path: tau = alpha a + beta b + gravity, with a = s-ddot and
// b = s-dot^2.
struct PathTorque {
  JointVector alpha = JointVector::Zero();    // M q'
  JointVector beta = JointVector::Zero();     // M q'' + c(q, q')
  JointVector gravity = JointVector::Zero();  // g(q)

  [[nodiscard]] JointVector at(double a, double b) const { return alpha * a + beta * b + gravity; }
};

// One joint's motor voltage along a path, kS aside:
//   V = alpha a + beta b + gamma sqrt(b) + offset + kS sgn(qdot),
// and its current times R is the same without the gamma term (the back-EMF). The Coulomb term is
// left to the caller, whose sign rule depends on the interval (topp_problem.hpp).
struct PathVoltage {
  double alpha = 0.0;   // volts per unit of a
  double beta = 0.0;    // volts per unit of b
  double gamma = 0.0;   // G q' / Kv: volts per unit of sqrt(b)
  double offset = 0.0;  // the gravity term in volts
};

// Joint `joint`'s PathVoltage from the chain's PathTorque and the path tangent q'.
[[nodiscard]] PathVoltage pathVoltage(const RigidBodyDrive& drive, const PathTorque& torque, const JointVector& dq_ds,
                                      int joint);

// The chain, the two links' bodies (index = joint index) and gravity g acting in -y.
class ChainDynamics {
 public:
  ChainDynamics(const JointChain& chain, const std::array<LinkInertia, kJointCount>& bodies,
                double gravity_mps2 = kStandardGravityMps2);

  [[nodiscard]] Eigen::Matrix2d massMatrix(const JointVector& q) const;
  // c(q, qdot): the Coriolis and centripetal terms, quadratic in qdot.
  [[nodiscard]] JointVector velocityTerms(const JointVector& q, const JointVector& qdot) const;
  [[nodiscard]] JointVector gravityTerms(const JointVector& q) const;
  [[nodiscard]] JointVector torque(const JointVector& q, const JointVector& qdot, const JointVector& qddot) const;
  // Along q(s): tau = M q' a + (M q'' + c(q, q')) b + g(q), since c(q, q' sdot) = c(q, q') b.
  [[nodiscard]] PathTorque alongPath(const JointVector& q, const JointVector& dq_ds, const JointVector& d2q_ds2) const;

  [[nodiscard]] const std::array<LinkInertia, kJointCount>& bodies() const { return bodies_; }

 private:
  // Positions and Jacobians of the chain at one q.
  struct Kinematics {
    std::array<Point2, kJointCount> cg_m;                  // each body's centre of mass, world
    std::array<Eigen::Matrix2d, kJointCount> cg_jacobian;  // d cg_k / dq
    std::array<Point2, kJointCount> pivot_m;               // each revolute joint's centre of rotation
    Eigen::Matrix2d pivot1_jacobian;                       // d pivot_1 / dq (pivot_0 is fixed)
    std::array<Point2, kJointCount> travel;                // each prismatic joint's unit direction
  };

  [[nodiscard]] Kinematics kinematics(const JointVector& q) const;
  [[nodiscard]] Eigen::Matrix2d massMatrix(const Kinematics& k) const;
  [[nodiscard]] JointVector velocityTerms(const Kinematics& k, const JointVector& qdot) const;
  [[nodiscard]] JointVector gravityTerms(const Kinematics& k) const;

  JointChain chain_;  // names dropped: copies never allocate
  std::array<LinkInertia, kJointCount> bodies_;
  // Row k: d(angle of link k)/dq, constant for a planar chain (1 for each revolute joint <= k).
  std::array<Eigen::RowVector2d, kJointCount> angle_jacobian_;
  double gravity_mps2_;
};

}  // namespace cyber::planner

#include "cyber/planner/chain.hpp"

#include <cmath>

namespace cyber::planner {
namespace {

// Omega v: v turned a quarter turn counter-clockwise (d/dphi R(phi) = Omega R(phi)).
Point2 quarterTurn(const Point2& v) { return Point2(-v.y(), v.x()); }

double sign(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

}  // namespace

LinkInertia combine(const LinkInertia& a, const LinkInertia& b) {
  LinkInertia out;
  out.mass_kg = a.mass_kg + b.mass_kg;
  if (out.mass_kg > 0.0) out.cg_m = (a.mass_kg * a.cg_m + b.mass_kg * b.cg_m) / out.mass_kg;
  out.moi_kgm2 = a.moi_kgm2 + a.mass_kg * (a.cg_m - out.cg_m).squaredNorm() + b.moi_kgm2 +
                 b.mass_kg * (b.cg_m - out.cg_m).squaredNorm();
  return out;
}

double RigidBodyDrive::voltsPerLoad() const {
  return motor.resistanceOhms() / (motor.ktNmPerAmp() * gearing * static_cast<double>(motor_count));
}

double RigidBodyDrive::backEmfVoltsPerRate() const { return gearing / motor.kvRadpsPerVolt(); }

double RigidBodyDrive::volts(double load, double qdot) const {
  return kS_volts * sign(qdot) + voltsPerLoad() * load + backEmfVoltsPerRate() * qdot;
}

double RigidBodyDrive::amps(double volts, double qdot) const {
  return (volts - backEmfVoltsPerRate() * qdot) / motor.resistanceOhms();
}

PathVoltage pathVoltage(const RigidBodyDrive& drive, const PathTorque& torque, const JointVector& dq_ds, int joint) {
  const double per_load = drive.voltsPerLoad();
  return PathVoltage{per_load * torque.alpha[joint], per_load * torque.beta[joint],
                     drive.backEmfVoltsPerRate() * dq_ds[joint], per_load * torque.gravity[joint]};
}

ChainDynamics::ChainDynamics(const JointChain& chain, const std::array<LinkInertia, kJointCount>& bodies,
                             double gravity_mps2)
    : bodies_(bodies), gravity_mps2_(gravity_mps2) {
  for (int j = 0; j < kJointCount; ++j) {
    chain_[j].type = chain[j].type;
    chain_[j].origin_m = chain[j].origin_m;
    chain_[j].axis_rad = chain[j].axis_rad;
    chain_[j].range = chain[j].range;
  }
  // A link turns with every revolute joint up to its own (algorithm.md, "Coupled rigid-body
  // dynamics"): its angle is affine in q, so this Jacobian is constant.
  for (int k = 0; k < kJointCount; ++k) {
    angle_jacobian_[k].setZero();
    for (int j = 0; j <= k; ++j) {
      if (chain_[j].type == JointType::kRevolute) angle_jacobian_[k][j] = 1.0;
    }
  }
}

ChainDynamics::Kinematics ChainDynamics::kinematics(const JointVector& q) const {
  const std::array<LinkFrame, kJointCount> frames = linkFrames(chain_, q);
  Kinematics k;
  for (int j = 0; j < kJointCount; ++j) {
    const LinkFrame parent = j == 0 ? LinkFrame{} : frames[0];
    // A revolute joint turns its link about the link's origin; a prismatic one slides it along
    // the joint axis turned with the parent.
    k.pivot_m[j] = frames[j].origin_m;
    k.travel[j] = parent.rotate(Point2(std::cos(chain_[j].axis_rad), std::sin(chain_[j].axis_rad)));
    k.cg_m[j] = frames[j].toWorld(bodies_[j].cg_m);
  }
  // Column j of the Jacobian of a point p moving with link i >= j: Omega (p - pivot_j) for a
  // revolute joint, its travel direction for a prismatic one.
  const auto column = [&](int j, const Point2& p) -> Point2 {
    return chain_[j].type == JointType::kRevolute ? quarterTurn(p - k.pivot_m[j]) : k.travel[j];
  };
  for (int i = 0; i < kJointCount; ++i) {
    for (int j = 0; j < kJointCount; ++j) {
      k.cg_jacobian[i].col(j) = j <= i ? column(j, k.cg_m[i]) : Point2::Zero();
    }
  }
  // Joint 1's pivot moves with link 0.
  k.pivot1_jacobian.col(0) = column(0, k.pivot_m[1]);
  k.pivot1_jacobian.col(1).setZero();
  return k;
}

Eigen::Matrix2d ChainDynamics::massMatrix(const Kinematics& k) const {
  Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
  for (int i = 0; i < kJointCount; ++i) {
    m += bodies_[i].mass_kg * k.cg_jacobian[i].transpose() * k.cg_jacobian[i] +
         bodies_[i].moi_kgm2 * angle_jacobian_[i].transpose() * angle_jacobian_[i];
  }
  return m;
}

JointVector ChainDynamics::velocityTerms(const Kinematics& k, const JointVector& qdot) const {
  // Each body's acceleration at qddot = 0, d/dt (J_i) qdot, summed column by column: a revolute
  // column Omega (p - pivot_j) changes at Omega (pdot - pivotdot_j), a prismatic one (a direction
  // turning with the parent link) at omega_parent Omega travel_j. The angular terms need none:
  // the angle Jacobians are constant.
  const std::array<Point2, kJointCount> pivot_velocity = {Point2::Zero(), k.pivot1_jacobian * qdot};
  JointVector c = JointVector::Zero();
  for (int i = 0; i < kJointCount; ++i) {
    const Point2 cg_velocity = k.cg_jacobian[i] * qdot;
    Point2 acceleration = Point2::Zero();
    for (int j = 0; j <= i; ++j) {
      if (chain_[j].type == JointType::kRevolute) {
        acceleration += qdot[j] * quarterTurn(cg_velocity - pivot_velocity[j]);
      } else {
        const double parent_rate = j == 0 ? 0.0 : angle_jacobian_[j - 1].dot(qdot);
        acceleration += qdot[j] * parent_rate * quarterTurn(k.travel[j]);
      }
    }
    c += bodies_[i].mass_kg * k.cg_jacobian[i].transpose() * acceleration;
  }
  return c;
}

JointVector ChainDynamics::gravityTerms(const Kinematics& k) const {
  // dV/dq with V = g sum_i m_i y_i: the y rows of the Jacobians.
  JointVector g = JointVector::Zero();
  for (int i = 0; i < kJointCount; ++i) {
    g += gravity_mps2_ * bodies_[i].mass_kg * k.cg_jacobian[i].row(1).transpose();
  }
  return g;
}

Eigen::Matrix2d ChainDynamics::massMatrix(const JointVector& q) const { return massMatrix(kinematics(q)); }

JointVector ChainDynamics::velocityTerms(const JointVector& q, const JointVector& qdot) const {
  return velocityTerms(kinematics(q), qdot);
}

JointVector ChainDynamics::gravityTerms(const JointVector& q) const { return gravityTerms(kinematics(q)); }

JointVector ChainDynamics::torque(const JointVector& q, const JointVector& qdot, const JointVector& qddot) const {
  const Kinematics k = kinematics(q);
  return massMatrix(k) * qddot + velocityTerms(k, qdot) + gravityTerms(k);
}

PathTorque ChainDynamics::alongPath(const JointVector& q, const JointVector& dq_ds, const JointVector& d2q_ds2) const {
  const Kinematics k = kinematics(q);
  const Eigen::Matrix2d m = massMatrix(k);
  return PathTorque{m * dq_ds, m * d2q_ds2 + velocityTerms(k, dq_ds), gravityTerms(k)};
}

}  // namespace cyber::planner

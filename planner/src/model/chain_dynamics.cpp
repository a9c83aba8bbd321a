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

ChainDynamics::ChainDynamics(const JointChain& chain, const PerJoint<LinkInertia>& bodies, double gravity_mps2)
    : bodies_(bodies), gravity_mps2_(gravity_mps2) {
  const int n = chain.size();
  for (int j = 0; j < n; ++j) {
    ChainJoint joint;
    joint.type = chain[j].type;
    joint.origin_m = chain[j].origin_m;
    joint.axis_rad = chain[j].axis_rad;
    joint.range = chain[j].range;
    chain_.push_back(joint);
  }
  // A link turns with every revolute joint up to its own (algorithm.md, "Coupled rigid-body
  // dynamics"): its angle is affine in q, so this Jacobian is constant.
  for (int k = 0; k < n; ++k) {
    JointRow row = JointRow::Zero(n);
    for (int j = 0; j <= k; ++j) {
      if (chain_[j].type == JointType::kRevolute) row[j] = 1.0;
    }
    angle_jacobian_.push_back(row);
  }
}

ChainDynamics::Kinematics ChainDynamics::kinematics(const JointVector& q) const {
  const int n = chain_.size();
  const PerJoint<LinkFrame> frames = linkFrames(chain_, q);
  Kinematics k;
  for (int j = 0; j < n; ++j) {
    const LinkFrame parent = j == 0 ? LinkFrame{} : frames[j - 1];
    // A revolute joint turns its link about the link's origin; a prismatic one slides it along
    // the joint axis turned with the parent.
    k.pivot_m.push_back(frames[j].origin_m);
    k.travel.push_back(parent.rotate(Point2(std::cos(chain_[j].axis_rad), std::sin(chain_[j].axis_rad))));
    k.cg_m.push_back(frames[j].toWorld(bodies_[j].cg_m));
  }
  // Column j of the Jacobian of a point p moving with link i >= j: Omega (p - pivot_j) for a
  // revolute joint, its travel direction for a prismatic one.
  const auto column = [&](int j, const Point2& p) -> Point2 {
    return chain_[j].type == JointType::kRevolute ? quarterTurn(p - k.pivot_m[j]) : k.travel[j];
  };
  for (int i = 0; i < n; ++i) {
    PointJacobian cg = PointJacobian::Zero(2, n);
    // Joint i's origin moves with the links before it, not with its own joint.
    PointJacobian pivot = PointJacobian::Zero(2, n);
    for (int j = 0; j <= i; ++j) {
      cg.col(j) = column(j, k.cg_m[i]);
      if (j < i) pivot.col(j) = column(j, k.pivot_m[i]);
    }
    k.cg_jacobian.push_back(cg);
    k.pivot_jacobian.push_back(pivot);
  }
  return k;
}

JointMatrix ChainDynamics::massMatrix(const Kinematics& k) const {
  const int n = chain_.size();
  JointMatrix m = JointMatrix::Zero(n, n);
  for (int i = 0; i < n; ++i) {
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
  const int n = chain_.size();
  PerJoint<Point2> pivot_velocity;
  for (int j = 0; j < n; ++j) pivot_velocity.push_back(k.pivot_jacobian[j] * qdot);
  JointVector c = JointVector::Zero(n);
  for (int i = 0; i < n; ++i) {
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
  const int n = chain_.size();
  JointVector g = JointVector::Zero(n);
  for (int i = 0; i < n; ++i) {
    g += gravity_mps2_ * bodies_[i].mass_kg * k.cg_jacobian[i].row(1).transpose();
  }
  return g;
}

JointMatrix ChainDynamics::massMatrix(const JointVector& q) const { return massMatrix(kinematics(q)); }

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
  const JointMatrix m = massMatrix(k);
  return PathTorque{m * dq_ds, m * d2q_ds2 + velocityTerms(k, dq_ds), gravityTerms(k)};
}

}  // namespace cyber::planner

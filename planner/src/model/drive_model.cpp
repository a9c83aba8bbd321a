#include "cyber/planner/chain.hpp"

#include <cmath>

namespace cyber::planner {

double DriveParams::gravityFactor(double psi_rad) const {
  switch (gravity) {
    case GravityModel::kConstant: return 1.0;
    case GravityModel::kCosine: return std::cos(psi_rad);
    case GravityModel::kSine: return std::sin(psi_rad);
    case GravityModel::kNone: return 0.0;
  }
  return 0.0;
}

double DriveParams::volts(double psi_rad, double qdot, double qddot) const {
  const double sign = static_cast<double>((qdot > 0.0) - (qdot < 0.0));
  return kS_volts * sign + kG_volts * gravityFactor(psi_rad) + kV * qdot + kA * qddot;
}

double DriveParams::amps(double v, double qdot) const {
  // DC motor: V = I R + omega / Kv with omega = gearing * qdot (algorithm.md section 3).
  return (v - gearing * qdot / motor.kvRadpsPerVolt()) / motor.resistanceOhms();
}

DriveModel::DriveModel(const JointChain& chain, const PerJoint<DriveParams>& drives) : drives_(drives) {
  for (const ChainJoint& joint : chain) {
    types_.push_back(joint.type);
    axes_rad_.push_back(joint.axis_rad);
  }
}

DriveModel::DriveModel(const PerJoint<DriveParams>& drives, const ChainDynamics& dynamics)
    : drives_(drives), dynamics_(dynamics) {}

RigidBodyDrive DriveModel::rigidBodyDrive(int joint) const {
  const DriveParams& d = drive(joint);
  return RigidBodyDrive{d.motor, d.motor_count, d.gearing, d.kS_volts, d.voltage_limit_volts, d.current_limit_amps};
}

double DriveModel::gravityAngle(int joint, const JointVector& q) const {
  // Revolute joints turn every later link by axis + q; a prismatic joint turns nothing and travels
  // along its own axis in its parent's orientation (chain.hpp).
  double angle = 0.0;
  for (int j = 0; j <= joint; ++j) {
    if (types_[j] == JointType::kRevolute) {
      angle += axes_rad_[j] + q[j];
    } else if (j == joint) {
      angle += axes_rad_[j];
    }
  }
  return angle;
}

JointVector DriveModel::volts(const JointVector& q, const JointVector& qdot, const JointVector& qddot) const {
  const int n = jointCount();
  JointVector out(n);
  if (dynamics_) {
    const JointVector load = dynamics_->torque(q, qdot, qddot);
    for (int j = 0; j < n; ++j) out[j] = rigidBodyDrive(j).volts(load[j], qdot[j]);
    return out;
  }
  for (int j = 0; j < n; ++j) out[j] = drive(j).volts(gravityAngle(j, q), qdot[j], qddot[j]);
  return out;
}

JointVector DriveModel::amps(const JointVector& v, const JointVector& qdot) const {
  const int n = jointCount();
  JointVector out(n);
  for (int j = 0; j < n; ++j) out[j] = drive(j).amps(v[j], qdot[j]);
  return out;
}

PerJoint<PathVoltage> DriveModel::pathVoltages(const PathPoint& p) const {
  const int n = jointCount();
  PerJoint<PathVoltage> out(n);
  if (dynamics_) {
    const PathTorque torque = dynamics_->alongPath(p.q, p.dq_ds, p.d2q_ds2);
    for (int j = 0; j < n; ++j) out[j] = pathVoltage(rigidBodyDrive(j), torque, p.dq_ds, j);
    return out;
  }
  // qdot = q' c and qddot = q' a + q'' b, so kV qdot + kA qddot = kA q' a + kA q'' b + kV q' c.
  for (int j = 0; j < n; ++j) {
    const DriveParams& d = drive(j);
    const double qp = p.dq_ds[j];
    out[j] = PathVoltage{d.kA * qp, d.kA * p.d2q_ds2[j], d.kV * qp, d.kG_volts * d.gravityFactor(gravityAngle(j, p.q))};
  }
  return out;
}

}  // namespace cyber::planner

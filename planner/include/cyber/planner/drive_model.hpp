#pragma once
// The voltage each joint's motors need for a motion, and the current they draw (docs/algorithm.md
// section 3): what the TOPP's rows, the trajectory's samples and the limit checks evaluate.

#include <array>
#include <optional>

#include "cyber/planner/chain_dynamics.hpp"
#include "cyber/planner/geometric_path.hpp"
#include "cyber/planner/joint_chain.hpp"
#include "cyber/planner/motor_params.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

// f(psi) of the WPILib feedforward's gravity term, psi the joint's absolute angle in the world
// (RobotModel::gravityAngle): 1, cos psi, sin psi or 0.
enum class GravityModel { kConstant, kCosine, kSine, kNone };

// One joint's drive: WPILib feedforward, the motors behind it and its limits.
// Joint units are m (prismatic) or rad (revolute); kV is V per unit/s, kA V per unit/s^2.
struct DriveParams {
  MotorParams motor;
  int motor_count = 1;
  double gearing = 1.0;  // motor rad per joint unit
  double kS_volts = 0.0;
  double kG_volts = 0.0;
  double kV = 0.0;
  double kA = 0.0;
  GravityModel gravity = GravityModel::kConstant;
  double voltage_limit_volts = 12.0;
  double current_limit_amps = 0.0;           // per motor
  std::optional<double> velocity_limit;      // joint units/s
  std::optional<double> acceleration_limit;  // joint units/s^2

  [[nodiscard]] double gravityFactor(double psi_rad) const;  // f(psi) of algorithm.md section 3
  // Feedforward voltage V(psi, qdot, qddot) and the per-motor current it draws.
  [[nodiscard]] double volts(double psi_rad, double qdot, double qddot) const;
  [[nodiscard]] double amps(double volts, double qdot) const;
};

// How the joints' voltages follow from their motion (docs/algorithm.md section 3): each joint's
// WPILib feedforward on its own, or the coupled rigid-body dynamics of the chain.
enum class DriveKind { kFeedforward, kRigidBody };

// Both joints' drives with what their voltages need of the chain (no names: copying it allocates
// nothing). Along a path a joint's voltage is alpha a + beta b + gamma sqrt(b) + offset +
// kS sgn(qdot) for either kind (PathVoltage, chain_dynamics.hpp); its current times R is the same
// with gamma less the back-EMF's G q' / Kv.
class DriveModel {
 public:
  DriveModel() = default;
  // WPILib feedforward per joint.
  DriveModel(const JointChain& chain, const std::array<DriveParams, kJointCount>& drives);
  // Coupled rigid-body dynamics: the drives' motors, gearing, kS and limits (their kG, kV, kA are
  // not used) driving `dynamics`.
  DriveModel(const std::array<DriveParams, kJointCount>& drives, const ChainDynamics& dynamics);

  [[nodiscard]] DriveKind kind() const { return dynamics_ ? DriveKind::kRigidBody : DriveKind::kFeedforward; }

  [[nodiscard]] const DriveParams& drive(int joint) const { return drives_[static_cast<size_t>(joint)]; }
  [[nodiscard]] const std::array<DriveParams, kJointCount>& drives() const { return drives_; }

  // psi_j(q): the absolute angle in the world of joint j's gravity term: a revolute joint's link
  // x axis, a prismatic joint's direction of travel.
  [[nodiscard]] double gravityAngle(int joint, const JointVector& q) const;
  [[nodiscard]] JointVector volts(const JointVector& q, const JointVector& qdot, const JointVector& qddot) const;
  [[nodiscard]] JointVector amps(const JointVector& volts, const JointVector& qdot) const;
  // Both joints' path coefficients at one path point.
  [[nodiscard]] std::array<PathVoltage, kJointCount> pathVoltages(const PathPoint& p) const;

 private:
  [[nodiscard]] RigidBodyDrive rigidBodyDrive(int joint) const;

  std::array<DriveParams, kJointCount> drives_{};
  std::optional<ChainDynamics> dynamics_;
  std::array<JointType, kJointCount> types_{JointType::kRevolute, JointType::kRevolute};
  std::array<double, kJointCount> axes_rad_{};
};

}  // namespace cyber::planner

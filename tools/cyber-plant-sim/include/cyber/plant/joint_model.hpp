#pragma once
// One simulated joint: a motor controller running a PD loop around the received feedforward, and
// the drive as WPILib's feedforward model describes it, read backwards (docs/testing.md,
// "Plant simulator"):
//
//   kA a = V - kS sgn(v) - kG g(q) - kV v          (the inverse of DriveParams::volts)
//   V    = clamp(V_ff + Kp (q_sp - q) + Kd (v_sp - v), +-voltage limit)   while commanded
//   V    = 0                                        in neutral (brake mode: kV v still damps)
//
// Integration is semi-implicit Euler at a fixed step: the velocity update treats the kV v term
// implicitly (so it is stable for any step), the position takes the new velocity. Friction is
// Coulomb with stiction: a joint at rest stays at rest while |V - kG g(q)| <= kS, and a joint whose
// velocity would change sign under friction stops at zero for that step. The joint range acts as
// hard stops. Pure functions; no clock, no I/O.

#include "cyber/planner/robot_model.hpp"

namespace cyber::plant {

// The drive figures the model uses, in joint units (m for the elevator, rad for the arm).
struct JointPlant {
  double kS_volts = 0.0;
  double kG_volts = 0.0;
  double kV = 0.0;  // V per unit/s
  double kA = 0.0;  // V per unit/s^2, > 0
  planner::GravityModel gravity = planner::GravityModel::kConstant;
  double voltage_limit_volts = 12.0;
  planner::JointRange range;

  static JointPlant fromDrive(const planner::DriveParams& drive, const planner::JointRange& range);
  [[nodiscard]] double gravityFactor(double q) const;
};

// The controller's feedback gains on top of the feedforward.
struct PdGains {
  double kp_volts_per_unit = 0.0;        // V per m or V per rad of position error
  double kd_volts_per_unit_per_s = 0.0;  // V per m/s or V per rad/s of velocity error
};

// What the controller tracks: a setpoint frame's content.
struct JointCommand {
  double position = 0.0;
  double velocity = 0.0;
  double feedforward_volts = 0.0;
};

struct JointState {
  double position = 0.0;
  double velocity = 0.0;
};

// The controller output for a command, clamped to the plant's voltage limit.
double controllerVolts(const JointPlant& plant, const PdGains& gains, const JointCommand& command,
                       const JointState& state);

// Advances the plant by dt_s > 0 under a constant applied voltage.
JointState stepPlant(const JointPlant& plant, const JointState& state, double applied_volts, double dt_s);

// The speed a joint settles at in neutral under gravity alone (brake mode), signed; 0 when
// friction holds it: -(|kG g(q)| - kS) / kV * sgn(kG g(q)).
double neutralSlideVelocity(const JointPlant& plant, double q);

}  // namespace cyber::plant

#pragma once
// The simulated mechanism: the chain's N joints (1 <= N <= planner::kMaxJoints, as the robot
// description has them) driven by the planner's own drive model read backwards
// (docs/testing.md, "Plant simulator"), so the simulator moves as the planner assumes, for either
// drive kind (WPILib feedforward per joint, or the coupled rigid-body dynamics of the chain):
//
//   V(q, v, a) = F(v) + A(q, v) a + b(q, v)        F_j = kS_j sgn(v_j): friction
//                                                   A: volts per unit of acceleration (N x N)
//   V          = clamp(V_ff + Kp (q_sp - q) + Kd (v_sp - v), +-voltage limit)   while commanded
//   V          = 0                                  in neutral (brake mode: back-EMF still damps)
//
// A and b come from DriveModel::volts at a = 0 and a = e_k (volts are affine in a for both
// kinds). Integration is semi-implicit Euler at a fixed step: the velocity update takes the
// velocity-proportional part of b implicitly ((A + dt D) dv = dt (V - F - b), D = db/dv by a
// central difference), so it is stable for any step; the position takes the new velocity.
// Friction is Coulomb with stiction: a joint at rest stays at rest while the voltage it would
// need to stay there differs from the applied one by at most kS, and a joint whose velocity would
// change sign under friction stops for that step; the free joints' velocity update is solved over
// the free joints only, the locked ones held at dv = 0. The joint ranges are hard stops. Pure: no
// clock, no I/O.

#include <array>

#include "cyber/planner.hpp"

namespace cyber::plant {

// The most joints a simulated chain has (the planner's bound); a plant's own N is jointCount().
inline constexpr int kMaxJoints = planner::kMaxJoints;

// One flag per joint, chain order (entries past N are ignored): fixed size, so `{false, true}`
// names joints 0 and 1 and leaves the rest false.
using JointFlags = std::array<bool, kMaxJoints>;

// The controller's feedback gains on top of the feedforward.
struct PdGains {
  double kp_volts_per_unit = 0.0;        // V per m or V per rad of position error
  double kd_volts_per_unit_per_s = 0.0;  // V per m/s or V per rad/s of velocity error
};

// What a controller tracks: a setpoint frame's content.
struct JointCommand {
  double position = 0.0;
  double velocity = 0.0;
  double feedforward_volts = 0.0;
};

// One joint's share of the state (what the state log and ARM_STATE carry per joint).
struct JointState {
  double position = 0.0;
  double velocity = 0.0;
};

// q and qdot carry N entries each (a default-constructed state has none: make it with atRest).
struct MechanismState {
  planner::JointVector q;
  planner::JointVector qdot;

  // At q, every joint at rest.
  [[nodiscard]] static MechanismState atRest(const planner::JointVector& q) {
    // Assigned rather than copy-constructed: g++ 12 cannot bound the size a copy constructor
    // hands to memcpy and fails the build with a false -Wstringop-overflow.
    MechanismState state;
    state.q = q;
    state.qdot = planner::JointVector::Zero(q.size());
    return state;
  }
};

class MechanismPlant {
 public:
  MechanismPlant() = default;  // no drive: only to be assigned over
  // One range per joint of the drive (drive.jointCount() of them).
  MechanismPlant(const planner::DriveModel& drive, const planner::PerJoint<planner::JointRange>& ranges);
  // The robot's drive model with `held` pieces (a held piece adds its mass to a rigid-body chain).
  static MechanismPlant fromRobot(const planner::RobotModel& robot, planner::HeldPieces held = {});

  // Advances by dt_s > 0 under constant applied voltages (state and volts: N entries). A joint
  // with `latched` set does not move (the simulator's joints rest at their initial pose until
  // their first setpoint).
  [[nodiscard]] MechanismState step(const MechanismState& state, const planner::JointVector& applied_volts, double dt_s,
                                    JointFlags latched = {}) const;

  // A: the voltage per unit of acceleration at (q, qdot); b: the voltage at zero acceleration
  // without friction (gravity, back-EMF, Coriolis).
  [[nodiscard]] planner::JointVector frictionlessVolts(const MechanismState& state,
                                                       const planner::JointVector& qddot) const;
  [[nodiscard]] const planner::DriveModel& drive() const { return drive_; }
  // N, the number of joints simulated.
  [[nodiscard]] int jointCount() const { return ranges_.size(); }
  [[nodiscard]] const planner::JointRange& range(int joint) const { return ranges_[joint]; }
  [[nodiscard]] double voltageLimit(int joint) const { return drive_.drive(joint).voltage_limit_volts; }

 private:
  planner::DriveModel drive_;
  planner::PerJoint<planner::JointRange> ranges_;
};

// The controller output for a command, clamped to the joint's voltage limit.
double controllerVolts(double voltage_limit_volts, const PdGains& gains, const JointCommand& command, double q,
                       double qdot);

// Feedback gains derived from the drive rather than tuned per robot: the error of joint j with
// the others held still obeys a_j e'' + (d_j + Kd) e' + Kp e = 0 (a_j = A_jj, d_j = D_jj at the
// middle of every range). Kp = a_j w^2 and Kd = 2 w a_j - d_j give a double pole at -w; where the
// back-EMF alone damps more than that (d_j > 2 w a_j, a heavily geared joint), Kd = 0 and
// Kp = d_j w - a_j w^2 put the slower of the two real poles at -w.
PdGains derivedGains(const MechanismPlant& plant, int joint, double bandwidth_radps);

// The steady speed of `joint` in neutral (0 V) at q with the other joints at rest: where its
// voltage balance b_j(q, v) + kS sgn(v) = 0; 0 when friction holds it.
double neutralSlideVelocity(const MechanismPlant& plant, int joint, const planner::JointVector& q);

}  // namespace cyber::plant

#include "cyber/plant/mechanism_plant.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace cyber::plant {

namespace {

using planner::JointMatrix;
using planner::JointVector;

double sign(double x) { return static_cast<double>((x > 0.0) - (x < 0.0)); }

// The linearisation of the drive at one state that a step needs.
struct Linearised {
  JointMatrix acceleration_volts;  // A: volts per unit of acceleration
  JointMatrix velocity_volts;      // D = d b / d v
  JointVector rest_volts;          // b at zero acceleration, no friction
};

Linearised linearise(const MechanismPlant& plant, const MechanismState& state) {
  const int n = plant.jointCount();
  Linearised out;
  out.acceleration_volts.resize(n, n);
  out.velocity_volts.resize(n, n);
  out.rest_volts = plant.frictionlessVolts(state, JointVector::Zero(n));
  for (int k = 0; k < n; ++k) {
    out.acceleration_volts.col(k) = plant.frictionlessVolts(state, JointVector::Unit(n, k)) - out.rest_volts;
    // Central difference: exact for the linear back-EMF, second order for Coriolis terms.
    const double h = 1e-6 * std::max(1.0, std::abs(state.qdot[k]));
    MechanismState up = state;
    MechanismState down = state;
    up.qdot[k] += h;
    down.qdot[k] -= h;
    out.velocity_volts.col(k) =
        (plant.frictionlessVolts(up, JointVector::Zero(n)) - plant.frictionlessVolts(down, JointVector::Zero(n))) /
        (2.0 * h);
  }
  return out;
}

// dv solving system_SS dv_S = rhs_S over the joints S that are not locked; dv = 0 on the locked
// ones. A single free joint is one division; the whole chain free is the full system.
JointVector solveFreeJoints(const JointMatrix& system, const JointVector& rhs, const JointFlags& locked) {
  const int n = static_cast<int>(rhs.size());
  std::array<int, kMaxJoints> free{};
  int free_count = 0;
  for (int j = 0; j < n; ++j) {
    if (!locked[static_cast<size_t>(j)]) free[static_cast<size_t>(free_count++)] = j;
  }
  JointVector dv = JointVector::Zero(n);
  if (free_count == 0) return dv;
  if (free_count == 1) {
    const int j = free[0];
    dv[j] = rhs[j] / system(j, j);
    return dv;
  }
  if (free_count == n) return system.partialPivLu().solve(rhs);
  JointMatrix sub(free_count, free_count);
  JointVector sub_rhs(free_count);
  for (int r = 0; r < free_count; ++r) {
    const int jr = free[static_cast<size_t>(r)];
    sub_rhs[r] = rhs[jr];
    for (int c = 0; c < free_count; ++c) sub(r, c) = system(jr, free[static_cast<size_t>(c)]);
  }
  const JointVector sub_dv = sub.partialPivLu().solve(sub_rhs);
  for (int r = 0; r < free_count; ++r) dv[free[static_cast<size_t>(r)]] = sub_dv[r];
  return dv;
}

}  // namespace

MechanismPlant::MechanismPlant(const planner::DriveModel& drive, const planner::PerJoint<planner::JointRange>& ranges)
    : drive_(drive), ranges_(ranges) {
  assert(ranges.size() == drive.jointCount());
}

MechanismPlant MechanismPlant::fromRobot(const planner::RobotModel& robot, planner::HeldPieces held) {
  planner::PerJoint<planner::JointRange> ranges;
  for (int j = 0; j < robot.jointCount(); ++j) ranges.push_back(robot.range(j));
  return MechanismPlant(robot.driveModel(held), ranges);
}

JointVector MechanismPlant::frictionlessVolts(const MechanismState& state, const JointVector& qddot) const {
  JointVector volts = drive_.volts(state.q, state.qdot, qddot);
  for (int j = 0; j < jointCount(); ++j) volts[j] -= drive_.drive(j).kS_volts * sign(state.qdot[j]);
  return volts;
}

MechanismState MechanismPlant::step(const MechanismState& state, const JointVector& applied_volts, double dt_s,
                                    JointFlags latched) const {
  const int n = jointCount();
  const Linearised lin = linearise(*this, state);
  // Joints that do not move this step: latched ones and those at rest that stiction holds.
  JointFlags locked{};
  std::array<double, kMaxJoints> friction_sign{};
  for (int j = 0; j < n; ++j) {
    locked[j] = latched[j] || state.qdot[j] == 0.0;
    friction_sign[j] = sign(state.qdot[j]);
  }
  JointVector dv = JointVector::Zero(n);
  // A joint breaking loose changes what the others need: at most one re-solve per joint.
  for (int pass = 0; pass <= n; ++pass) {
    // (A + dt D)_SS dv_S = dt (V - F - b)_S over the free joints S; locked joints keep dv = 0.
    const JointMatrix system = lin.acceleration_volts + dt_s * lin.velocity_volts;
    JointVector rhs(n);
    for (int j = 0; j < n; ++j) {
      rhs[j] = dt_s * (applied_volts[j] - drive_.drive(j).kS_volts * friction_sign[j] - lin.rest_volts[j]);
    }
    dv = solveFreeJoints(system, rhs, locked);
    // A resting joint stays put while the voltage it needs to stay differs from the applied one
    // by at most kS; otherwise it breaks loose in the direction of the difference.
    const JointVector needed = lin.acceleration_volts * (dv / dt_s) + lin.rest_volts;
    bool changed = false;
    for (int j = 0; j < n; ++j) {
      if (!locked[j] || latched[j]) continue;
      const double residual = applied_volts[j] - needed[j];
      if (std::abs(residual) > drive_.drive(j).kS_volts) {
        locked[j] = false;
        friction_sign[j] = sign(residual);
        changed = true;
      }
    }
    if (!changed) break;
  }

  MechanismState next = state;
  for (int j = 0; j < n; ++j) {
    if (locked[j]) {
      next.qdot[j] = 0.0;
      continue;
    }
    next.qdot[j] = state.qdot[j] + dv[j];
    // Friction can stop a joint, never reverse it within a step (nor push one backwards that it
    // just broke loose).
    if (friction_sign[j] != 0.0 && sign(next.qdot[j]) == -friction_sign[j]) next.qdot[j] = 0.0;
    next.q[j] = state.q[j] + dt_s * next.qdot[j];
    const planner::JointRange& r = range(j);
    if (next.q[j] <= r.min) {
      next.q[j] = r.min;
      next.qdot[j] = std::max(next.qdot[j], 0.0);
    } else if (next.q[j] >= r.max) {
      next.q[j] = r.max;
      next.qdot[j] = std::min(next.qdot[j], 0.0);
    }
  }
  return next;
}

double controllerVolts(double voltage_limit_volts, const PdGains& gains, const JointCommand& command, double q,
                       double qdot) {
  const double volts = command.feedforward_volts + gains.kp_volts_per_unit * (command.position - q) +
                       gains.kd_volts_per_unit_per_s * (command.velocity - qdot);
  return std::clamp(volts, -voltage_limit_volts, voltage_limit_volts);
}

PdGains derivedGains(const MechanismPlant& plant, int joint, double bandwidth_radps) {
  const int n = plant.jointCount();
  MechanismState middle{JointVector(n), JointVector::Zero(n)};
  for (int j = 0; j < n; ++j) middle.q[j] = 0.5 * (plant.range(j).min + plant.range(j).max);
  const Linearised lin = linearise(plant, middle);
  const double a = lin.acceleration_volts(joint, joint);
  const double d = lin.velocity_volts(joint, joint);
  const double w = bandwidth_radps;
  if (d <= 2.0 * w * a) return PdGains{a * w * w, 2.0 * w * a - d};  // double pole at -w
  // The back-EMF alone damps more than critically: no Kd, and Kp puts the slower pole at -w
  // (a w^2 would leave it at about -a w^2 / d, far slower).
  return PdGains{d * w - a * w * w, 0.0};
}

double neutralSlideVelocity(const MechanismPlant& plant, int joint, const JointVector& q) {
  const double kS = plant.drive().drive(joint).kS_volts;
  const JointVector no_acceleration = JointVector::Zero(q.size());
  const auto balance = [&](double v) {
    MechanismState state = MechanismState::atRest(q);
    state.qdot[joint] = v;
    return plant.frictionlessVolts(state, no_acceleration)[joint] + kS * sign(v);
  };
  const double pull = plant.frictionlessVolts(MechanismState::atRest(q), no_acceleration)[joint];
  if (std::abs(pull) <= kS) return 0.0;
  // The joint moves against the pull's sign until back-EMF balances it: bracket, then bisect.
  const double direction = -sign(pull);
  double lo = 0.0;
  double hi = direction;
  for (int i = 0; i < 60 && sign(balance(hi)) == sign(pull); ++i) hi *= 2.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (sign(balance(mid)) == sign(pull) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace cyber::plant

#include "cyber/plant/joint_model.hpp"

#include <algorithm>
#include <cmath>

namespace cyber::plant {

namespace {

double sign(double x) { return static_cast<double>((x > 0.0) - (x < 0.0)); }

}  // namespace

JointPlant JointPlant::fromDrive(const planner::DriveParams& drive, const planner::JointRange& range) {
  JointPlant plant;
  plant.kS_volts = drive.kS_volts;
  plant.kG_volts = drive.kG_volts;
  plant.kV = drive.kV;
  plant.kA = drive.kA;
  plant.gravity = drive.gravity;
  plant.voltage_limit_volts = drive.voltage_limit_volts;
  plant.range = range;
  return plant;
}

double JointPlant::gravityFactor(double q) const {
  return gravity == planner::GravityModel::kCosine ? std::cos(q) : 1.0;
}

double controllerVolts(const JointPlant& plant, const PdGains& gains, const JointCommand& command,
                       const JointState& state) {
  const double volts = command.feedforward_volts + gains.kp_volts_per_unit * (command.position - state.position) +
                       gains.kd_volts_per_unit_per_s * (command.velocity - state.velocity);
  return std::clamp(volts, -plant.voltage_limit_volts, plant.voltage_limit_volts);
}

JointState stepPlant(const JointPlant& plant, const JointState& state, double applied_volts, double dt_s) {
  // Everything but friction and back-EMF, in volts.
  const double drive_volts = applied_volts - plant.kG_volts * plant.gravityFactor(state.position);
  JointState next = state;
  if (state.velocity == 0.0 && std::abs(drive_volts) <= plant.kS_volts) {
    next.velocity = 0.0;  // stiction holds
  } else {
    // Friction opposes the motion, or the pull that breaks the joint loose.
    const double friction_sign = state.velocity != 0.0 ? sign(state.velocity) : sign(drive_volts);
    const double net_volts = drive_volts - plant.kS_volts * friction_sign;
    // kA (v' - v) / dt = net - kV v'  (back-EMF implicit).
    next.velocity = (state.velocity + dt_s * net_volts / plant.kA) / (1.0 + dt_s * plant.kV / plant.kA);
    // Friction can stop a joint, never reverse it within a step.
    if (state.velocity != 0.0 && sign(next.velocity) != sign(state.velocity)) next.velocity = 0.0;
  }
  next.position = state.position + dt_s * next.velocity;
  if (next.position <= plant.range.min) {
    next.position = plant.range.min;
    next.velocity = std::max(next.velocity, 0.0);
  } else if (next.position >= plant.range.max) {
    next.position = plant.range.max;
    next.velocity = std::min(next.velocity, 0.0);
  }
  return next;
}

double neutralSlideVelocity(const JointPlant& plant, double q) {
  const double gravity_volts = plant.kG_volts * plant.gravityFactor(q);
  if (std::abs(gravity_volts) <= plant.kS_volts) return 0.0;
  return -(std::abs(gravity_volts) - plant.kS_volts) / plant.kV * sign(gravity_volts);
}

}  // namespace cyber::plant

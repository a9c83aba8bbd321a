#include "cyber/plant/plant_simulation.hpp"

#include <algorithm>
#include <cmath>

namespace cyber::plant {

SimulationSettings::SimulationSettings(const MechanismPlant& mechanism, double controller_bandwidth_radps)
    : plant(mechanism) {
  for (int joint = 0; joint < kJointCount; ++joint)
    gains[joint] = derivedGains(plant, joint, controller_bandwidth_radps);
}

PlantSimulation::PlantSimulation(const SimulationSettings& settings, const planner::JointVector& initial_q)
    : settings_(settings) {
  state_.q = initial_q;
}

void PlantSimulation::advanceTo(double t_s) {
  // Every step that starts before t_s runs, so the state is at the first grid time at or after
  // t_s; the tolerance lets t = k * step land on step k exactly despite rounding.
  const double steps_wanted = std::ceil(t_s / settings_.step_s - 1e-9);
  while (static_cast<double>(steps_) < steps_wanted) step();
}

void PlantSimulation::receiveSetpoint(int joint, const JointCommand& command, double t_s) {
  advanceTo(t_s);
  latest_[joint] = ReceivedSetpoint{command, t_s};
  disabled_[joint] = false;
}

void PlantSimulation::disableOutputs() { disabled_.fill(true); }

std::optional<JointCommand> PlantSimulation::effectiveCommand(int joint, double t_s) const {
  const auto& latest = latest_[joint];
  if (!latest || disabled_[joint]) return std::nullopt;
  const double age_s = t_s - latest->arrival_s;
  if (age_s > settings_.setpoint_timeout_s) return std::nullopt;
  JointCommand command = latest->command;
  command.position += command.velocity * std::max(age_s, 0.0);
  return command;
}

void PlantSimulation::step() {
  const double now_s = time_s();
  std::array<bool, kJointCount> latched{};
  for (int joint = 0; joint < kJointCount; ++joint) {
    latched[joint] = !latest_[joint];  // resting at the initial pose until its first setpoint
    const auto command = effectiveCommand(joint, now_s);
    applied_volts_[joint] = command ? controllerVolts(settings_.plant.voltageLimit(joint), settings_.gains[joint],
                                                      *command, state_.q[joint], state_.qdot[joint])
                                    : 0.0;
  }
  state_ = settings_.plant.step(state_, planner::JointVector(applied_volts_[0], applied_volts_[1]), settings_.step_s,
                                latched);
  ++steps_;
}

}  // namespace cyber::plant

#include "cyber/plant/plant_simulation.hpp"

#include <algorithm>
#include <cmath>

namespace cyber::plant {

PlantSimulation::PlantSimulation(const SimulationSettings& settings, const planner::JointVector& initial_q)
    : settings_(settings) {
  for (int joint = 0; joint < kJointCount; ++joint) states_[joint].position = initial_q[joint];
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

planner::JointVector PlantSimulation::positions() const { return {states_[0].position, states_[1].position}; }

planner::JointVector PlantSimulation::velocities() const { return {states_[0].velocity, states_[1].velocity}; }

void PlantSimulation::step() {
  const double now_s = time_s();
  for (int joint = 0; joint < kJointCount; ++joint) {
    if (!latest_[joint]) continue;  // resting at the initial pose until its first setpoint
    const JointPlant& plant = settings_.plants[joint];
    const auto command = effectiveCommand(joint, now_s);
    applied_volts_[joint] = command ? controllerVolts(plant, settings_.gains[joint], *command, states_[joint]) : 0.0;
    states_[joint] = stepPlant(plant, states_[joint], applied_volts_[joint], settings_.step_s);
  }
  ++steps_;
}

}  // namespace cyber::plant

#include "cyber/plant/plant_simulation.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace cyber::plant {

SimulationSettings::SimulationSettings(const MechanismPlant& mechanism, double controller_bandwidth_radps)
    : plant(mechanism) {
  for (int joint = 0; joint < plant.jointCount(); ++joint) {
    gains.push_back(derivedGains(plant, joint, controller_bandwidth_radps));
  }
}

PlantSimulation::PlantSimulation(const SimulationSettings& settings, const planner::JointVector& initial_q)
    : settings_(settings),
      state_(MechanismState::atRest(initial_q)),
      applied_volts_(planner::JointVector::Zero(settings.plant.jointCount())) {
  assert(initial_q.size() == settings.plant.jointCount());
}

void PlantSimulation::advanceTo(double t_s) {
  // Every step that starts before t_s runs, so the state is at the first grid time at or after
  // t_s; the tolerance lets t = k * step land on step k exactly despite rounding.
  const double steps_wanted = std::ceil(t_s / settings_.step_s - 1e-9);
  while (static_cast<double>(steps_) < steps_wanted) step();
}

void PlantSimulation::receiveSetpoint(int joint, const JointCommand& command, double t_s) {
  advanceTo(t_s);
  latest_[static_cast<size_t>(joint)] = ReceivedSetpoint{command, t_s};
  disabled_[static_cast<size_t>(joint)] = false;
}

void PlantSimulation::disableOutputs() { disabled_.fill(true); }

std::optional<JointCommand> PlantSimulation::effectiveCommand(int joint, double t_s) const {
  const auto& latest = latest_[static_cast<size_t>(joint)];
  if (!latest || disabled_[static_cast<size_t>(joint)]) return std::nullopt;
  const double age_s = t_s - latest->arrival_s;
  if (age_s > settings_.setpoint_timeout_s) return std::nullopt;
  JointCommand command = latest->command;
  command.position += command.velocity * std::max(age_s, 0.0);
  return command;
}

void PlantSimulation::step() {
  const double now_s = time_s();
  JointFlags latched{};
  for (int joint = 0; joint < jointCount(); ++joint) {
    const auto j = static_cast<size_t>(joint);
    latched[j] = !latest_[j];  // resting at the initial pose until its first setpoint
    const auto command = effectiveCommand(joint, now_s);
    applied_volts_[joint] = command ? controllerVolts(settings_.plant.voltageLimit(joint), settings_.gains[joint],
                                                      *command, state_.q[joint], state_.qdot[joint])
                                    : 0.0;
  }
  state_ = settings_.plant.step(state_, applied_volts_, settings_.step_s, latched);
  ++steps_;
}

}  // namespace cyber::plant

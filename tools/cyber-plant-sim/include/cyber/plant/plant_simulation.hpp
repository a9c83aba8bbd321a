#pragma once
// The simulated mechanism with one motor controller per joint (as many as the plant has), stepped
// on a fixed time grid.
// Each controller tracks the latest setpoint it received, its position advanced by its velocity
// since it arrived (the frames come every 5 ms; holding the position still would lag by v * 5 ms).
// A controller that has heard nothing for setpoint_timeout_s, or that saw a broadcast disable since
// its latest setpoint, goes neutral (0 V, brake mode). Until its first setpoint a joint rests at
// its initial pose (as on a latch), so a test starts from a known pose however long the daemon
// takes to come up. Pure: time is whatever the caller passes.

#include <array>
#include <optional>

#include "cyber/planner.hpp"
#include "cyber/plant/mechanism_plant.hpp"

namespace cyber::plant {

// The closed-loop bandwidth the simulated controllers' gains are derived for (derivedGains): a
// position loop on a 1 kHz motor controller, well below that loop's rate and the motors'
// electrical time constants. The reference robot's hand-tuned gains gave 63 and 104 rad/s.
inline constexpr double kDefaultControllerBandwidth_radps = 100.0;

struct SimulationSettings {
  SimulationSettings() = default;  // no plant: only to be assigned over
  explicit SimulationSettings(const MechanismPlant& mechanism,
                              double controller_bandwidth_radps = kDefaultControllerBandwidth_radps);

  MechanismPlant plant;
  planner::PerJoint<PdGains> gains;  // one per joint, derived from the plant at the bandwidth given
  double step_s = 0.001;             // controller and integration step (a 1 kHz loop)
  double setpoint_timeout_s = 0.1;   // no setpoint for longer: neutral
};

struct ReceivedSetpoint {
  JointCommand command;
  double arrival_s = 0.0;
};

class PlantSimulation {
 public:
  // initial_q: one position per joint of settings.plant, within its ranges.
  PlantSimulation(const SimulationSettings& settings, const planner::JointVector& initial_q);

  // Runs every whole step that starts before t_s: the state is then at the first grid time at or
  // after t_s (at most one step ahead, driven only by setpoints that arrived before t_s). Never
  // goes back in time.
  void advanceTo(double t_s);
  // A setpoint frame for `joint` arrived at t_s: advances to t_s first, then takes it. Clears a
  // broadcast-disable neutral.
  void receiveSetpoint(int joint, const JointCommand& command, double t_s);
  // Broadcast disable: every controller goes neutral now, until its next setpoint.
  void disableOutputs();

  // The command a controller tracks at t_s, or nothing when it is neutral.
  [[nodiscard]] std::optional<JointCommand> effectiveCommand(int joint, double t_s) const;

  [[nodiscard]] int jointCount() const { return settings_.plant.jointCount(); }
  [[nodiscard]] double time_s() const { return static_cast<double>(steps_) * settings_.step_s; }
  [[nodiscard]] const MechanismState& state() const { return state_; }
  [[nodiscard]] JointState state(int joint) const { return {state_.q[joint], state_.qdot[joint]}; }
  [[nodiscard]] const planner::JointVector& positions() const { return state_.q; }
  [[nodiscard]] const planner::JointVector& velocities() const { return state_.qdot; }
  // Voltage the controller applied during the latest step.
  [[nodiscard]] double appliedVolts(int joint) const { return applied_volts_[joint]; }
  [[nodiscard]] const std::optional<ReceivedSetpoint>& latestSetpoint(int joint) const {
    return latest_[static_cast<size_t>(joint)];
  }
  [[nodiscard]] const SimulationSettings& settings() const { return settings_; }

 private:
  void step();

  SimulationSettings settings_;
  long long steps_ = 0;  // time = steps_ * step_s, so long runs do not accumulate rounding
  MechanismState state_;
  planner::JointVector applied_volts_;  // N entries
  std::array<std::optional<ReceivedSetpoint>, kMaxJoints> latest_{};
  JointFlags disabled_{};
};

}  // namespace cyber::plant

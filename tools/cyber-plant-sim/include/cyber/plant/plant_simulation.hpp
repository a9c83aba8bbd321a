#pragma once
// The simulated elevator and arm with their motor controllers, stepped on a fixed time grid.
// Each controller tracks the latest setpoint it received, its position advanced by its velocity
// since it arrived (the frames come every 5 ms; holding the position still would lag by v * 5 ms).
// A controller that has heard nothing for setpoint_timeout_s, or that saw a broadcast disable since
// its latest setpoint, goes neutral (0 V, brake mode). Until its first setpoint a joint rests at
// its initial pose (as on a latch), so a test starts from a known pose however long the daemon
// takes to come up. Pure: time is whatever the caller passes.

#include <array>
#include <optional>

#include "cyber/planner/types.hpp"
#include "cyber/plant/joint_model.hpp"

namespace cyber::plant {

inline constexpr int kJointCount = planner::kJointCount;  // joint 0, joint 1 in chain order

struct SimulationSettings {
  std::array<JointPlant, kJointCount> plants;
  std::array<PdGains, kJointCount> gains;
  double step_s = 0.001;            // controller and integration step (a 1 kHz loop)
  double setpoint_timeout_s = 0.1;  // no setpoint for longer: neutral
};

// Default feedback gains of the simulated controllers. With the reference drives they give error
// dynamics kA e'' + (kV + Kd) e' + Kp e = 0 close to critically damped (elevator 63 rad/s, arm
// 104 rad/s) and a friction dead band kS / Kp of 1 mm and 2.5 mrad.
inline constexpr PdGains kDefaultElevatorGains{150.0, 1.0};
inline constexpr PdGains kDefaultArmGains{60.0, 0.1};

struct ReceivedSetpoint {
  JointCommand command;
  double arrival_s = 0.0;
};

class PlantSimulation {
 public:
  PlantSimulation(const SimulationSettings& settings, const planner::JointVector& initial_q);

  // Runs every whole step that starts before t_s: the state is then at the first grid time at or
  // after t_s (at most one step ahead, driven only by setpoints that arrived before t_s). Never
  // goes back in time.
  void advanceTo(double t_s);
  // A setpoint frame for `joint` arrived at t_s: advances to t_s first, then takes it. Clears a
  // broadcast-disable neutral.
  void receiveSetpoint(int joint, const JointCommand& command, double t_s);
  // Broadcast disable: both controllers go neutral now, until their next setpoint.
  void disableOutputs();

  // The command a controller tracks at t_s, or nothing when it is neutral.
  [[nodiscard]] std::optional<JointCommand> effectiveCommand(int joint, double t_s) const;

  [[nodiscard]] double time_s() const { return static_cast<double>(steps_) * settings_.step_s; }
  [[nodiscard]] const JointState& state(int joint) const { return states_[joint]; }
  [[nodiscard]] planner::JointVector positions() const;
  [[nodiscard]] planner::JointVector velocities() const;
  // Voltage the controller applied during the latest step.
  [[nodiscard]] double appliedVolts(int joint) const { return applied_volts_[joint]; }
  [[nodiscard]] const std::optional<ReceivedSetpoint>& latestSetpoint(int joint) const { return latest_[joint]; }
  [[nodiscard]] const SimulationSettings& settings() const { return settings_; }

 private:
  void step();

  SimulationSettings settings_;
  long long steps_ = 0;  // time = steps_ * step_s, so long runs do not accumulate rounding
  std::array<JointState, kJointCount> states_{};
  std::array<double, kJointCount> applied_volts_{};
  std::array<std::optional<ReceivedSetpoint>, kJointCount> latest_{};
  std::array<bool, kJointCount> disabled_{};
};

}  // namespace cyber::plant

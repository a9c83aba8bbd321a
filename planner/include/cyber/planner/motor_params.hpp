#pragma once
// A DC motor as WPILib's DCMotor describes it (docs/algorithm.md section 3): V = I R + omega / Kv,
// torque = Kt I.

namespace cyber::planner {

// DC motor figures as WPILib's DCMotor gives them.
struct MotorParams {
  double nominal_voltage_volts = 12.0;
  double stall_torque_nm = 0.0;
  double stall_current_amps = 0.0;
  double free_current_amps = 0.0;
  double free_speed_radps = 0.0;

  [[nodiscard]] double resistanceOhms() const { return nominal_voltage_volts / stall_current_amps; }
  // Kv in rad/s per volt of back-EMF.
  [[nodiscard]] double kvRadpsPerVolt() const {
    return free_speed_radps / (nominal_voltage_volts - resistanceOhms() * free_current_amps);
  }
  [[nodiscard]] double ktNmPerAmp() const { return stall_torque_nm / stall_current_amps; }
};

}  // namespace cyber::planner

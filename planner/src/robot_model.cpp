#include "cyber/planner/robot_model.hpp"

#include <cmath>

namespace cyber::planner {

double DriveParams::gravityFactor(double q) const { return gravity == GravityModel::kCosine ? std::cos(q) : 1.0; }

double DriveParams::volts(double q, double qdot, double qddot) const {
  const double sign = static_cast<double>((qdot > 0.0) - (qdot < 0.0));
  return kS_volts * sign + kG_volts * gravityFactor(q) + kV * qdot + kA * qddot;
}

double DriveParams::amps(double v, double qdot) const {
  // DC motor: V = I R + omega / Kv with omega = gearing * qdot (algorithm.md section 3).
  return (v - gearing * qdot / motor.kvRadpsPerVolt()) / motor.resistanceOhms();
}

int RobotModel::sceneIndex(const std::string& scene_name) const {
  for (size_t i = 0; i < scenes.size(); ++i) {
    if (scenes[i].name == scene_name) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace cyber::planner

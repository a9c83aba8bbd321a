// The drives of a random robot: motors of the shipped configs (and two more of WPILib's table),
// gearings that cross a joint's range in 0.3-1.5 s, and as many motors as hold the load.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "random_robot_chain.hpp"

namespace cyber::test::random_robot {
namespace {

using planner::JointType;

// config/*.toml's motors, and WPILib DCMotor's Kraken X44 and NEO Vortex.
constexpr Motor kMotors[] = {
    {"kraken_x60", 7.09, 366.0, 2.0, 6000.0}, {"kraken_x60_foc", 9.37, 483.0, 2.0, 5800.0},
    {"kraken_x44", 4.05, 275.0, 1.4, 7530.0}, {"neo", 2.6, 105.0, 1.8, 5676.0},
    {"neo_vortex", 3.6, 211.0, 3.6, 6784.0},
};
constexpr double kGravityMps2 = 9.80665;
// The torque (force) the motors give at their current limit over the most gravity asks of them:
// what is left accelerates the joint.
constexpr double kHoldingMargin = 2.5;
constexpr int kMaxMotors = 4;
// A joint crosses its range in about this many times the range over its top speed (the
// acceleration at each end).
constexpr double kRangeTimeOverCruise = 1.3;

// The most each joint carries: weight (N m, or N along a prismatic joint) and inertia
// (kg m^2, or kg), bounds over every pose with every piece held.
struct Load {
  double gravity = 0.0;
  double inertia = 0.0;
};

double freeSpeedRadps(const Motor& m) { return m.free_speed_rpm * 2.0 * std::numbers::pi / 60.0; }

Load loadOf(const std::vector<JointDraw>& chain, const std::vector<PieceDraw>& pieces, size_t j) {
  Load load;
  double to_link_m = 0.0;  // from joint j's axis to the origin of link k, at most
  const auto add = [&](const Body& b, double r_m) {
    const bool pivot = chain[j].type == JointType::kRevolute;
    load.gravity += kGravityMps2 * b.mass_kg * (pivot ? r_m : 1.0);
    load.inertia += pivot ? b.mass_kg * r_m * r_m + b.moi_kgm2 : b.mass_kg;
  };
  for (size_t k = j; k < chain.size(); ++k) {
    if (k > j)
      to_link_m += chain[k].origin_m.norm() + (chain[k].type == JointType::kPrismatic ? chain[k].range.max : 0.0);
    add(chain[k].body, to_link_m + chain[k].body.cg_m.norm());
  }
  for (const PieceDraw& p : pieces) add(p.body, to_link_m + p.body.cg_m.norm());
  return load;
}

// Motors and gearing: the range crossed in the drawn time, and enough motors (or, past
// kMaxMotors, enough gearing) to hold the load with kHoldingMargin.
void gear(Draws& d, const JointDraw& joint, const Load& load, DriveDraw& drive) {
  const Motor& m = *drive.motor;
  const double range_time_s = d.uniform(0.3, 1.5);
  drive.gearing = freeSpeedRadps(m) * range_time_s / (kRangeTimeOverCruise * (joint.range.max - joint.range.min));
  const double per_motor = m.stall_torque_nm / m.stall_current_amps * drive.current_limit_amps;
  const double needed = kHoldingMargin * load.gravity / per_motor;
  drive.count = std::clamp(static_cast<int>(std::ceil(needed / drive.gearing)), drive.count, kMaxMotors);
  drive.gearing = std::max(drive.gearing, needed / kMaxMotors);
  drive.gearing = std::ceil(drive.gearing * 10.0) / 10.0;
}

void limits(Draws& d, const Load& load, DriveDraw& drive) {
  const Motor& m = *drive.motor;
  if (d.chance(0.2)) {
    drive.velocity_limit = std::round(d.uniform(0.5, 0.9) * freeSpeedRadps(m) / drive.gearing * 100.0) / 100.0;
  }
  if (d.chance(0.15)) {
    const double force =
        drive.count * m.stall_torque_nm / m.stall_current_amps * drive.current_limit_amps * drive.gearing;
    drive.acceleration_limit =
        std::max(0.1, std::round(d.uniform(0.4, 0.9) * (force - load.gravity) / load.inertia * 10.0) / 10.0);
  }
}

// WPILib's feedforward as a team derives it from the motor and the mechanism: kV the back-EMF,
// kA and kG the current the inertia and the weight ask for, times the resistance.
void feedforward(const JointDraw& joint, const Load& load, DriveDraw& drive) {
  const Motor& m = *drive.motor;
  const double r_ohms = 12.0 / m.stall_current_amps;
  const double kv_radps_per_volt = freeSpeedRadps(m) / (12.0 - r_ohms * m.free_current_amps);
  const double volts_per_load = r_ohms / (m.stall_torque_nm / m.stall_current_amps * drive.gearing * drive.count);
  drive.gravity = joint.type == JointType::kRevolute ? "cosine" : "sine";
  drive.kV = std::round(drive.gearing / kv_radps_per_volt * 1e4) / 1e4;
  drive.kA = std::max(1e-6, std::round(load.inertia * volts_per_load * 1e6) / 1e6);
  drive.kG_volts = std::round(load.gravity * volts_per_load * 1e4) / 1e4;
}

}  // namespace

std::vector<DriveDraw> drawDrives(Draws& d, const std::vector<JointDraw>& chain, const std::vector<PieceDraw>& pieces,
                                  bool rigid_body) {
  std::vector<DriveDraw> drives;
  for (size_t j = 0; j < chain.size(); ++j) {
    DriveDraw drive;
    drive.motor = &kMotors[d.integer(0, std::size(kMotors) - 1)];
    drive.count = d.integer(1, 2);
    drive.kS_volts = d.rounded(0.0, 0.3, 100.0);
    drive.voltage_limit_volts = d.rounded(10.0, 12.0, 2.0);
    drive.current_limit_amps = d.rounded(30.0, std::clamp(0.45 * drive.motor->stall_current_amps, 30.0, 80.0), 1.0);
    const Load load = loadOf(chain, pieces, j);
    gear(d, chain[j], load, drive);
    limits(d, load, drive);
    if (!rigid_body) feedforward(chain[j], load, drive);
    drives.push_back(drive);
  }
  return drives;
}

}  // namespace cyber::test::random_robot

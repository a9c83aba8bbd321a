#include "read_drives.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <string>

namespace cyber::config::detail {
namespace {

planner::MotorParams readMotor(TableReader motor) {
  planner::MotorParams m;
  m.nominal_voltage_volts = motor.number("nominal_voltage_volts", kPositive);
  m.stall_torque_nm = motor.number("stall_torque_nm", kPositive);
  m.stall_current_amps = motor.number("stall_current_amps", kPositive);
  m.free_current_amps = motor.number("free_current_amps", Bounds{0.0, m.stall_current_amps, false});
  m.free_speed_radps = motor.number("free_speed_rpm", kPositive) * 2.0 * std::numbers::pi / 60.0;
  motor.finish();
  return m;
}

planner::GravityModel gravityModel(TableReader& drive) {
  const std::string gravity = drive.string("gravity");
  if (gravity == "constant") return planner::GravityModel::kConstant;
  if (gravity == "cosine") return planner::GravityModel::kCosine;
  if (gravity == "sine") return planner::GravityModel::kSine;
  if (gravity == "none") return planner::GravityModel::kNone;
  drive.fail("gravity", "expected \"constant\", \"cosine\", \"sine\" or \"none\", got \"" + gravity + "\"");
}

planner::DriveKind driveKind(TableReader& drive) {
  const std::string kind = drive.string("kind");
  if (kind == "feedforward") return planner::DriveKind::kFeedforward;
  if (kind == "rigid_body") return planner::DriveKind::kRigidBody;
  drive.fail("kind", "expected \"feedforward\" or \"rigid_body\", got \"" + kind + "\"");
}

// The motors behind a joint, its Coulomb friction and its limits: what both kinds share.
void readMotors(TableReader& drive, const std::map<std::string, planner::MotorParams>& motors,
                planner::DriveParams& d) {
  const std::string motor = drive.string("motor", "a motor's name as a string, a key of [motors]");
  const auto it = motors.find(motor);
  if (it == motors.end()) drive.fail("motor", "unknown motor \"" + motor + "\" (define it under [motors])");
  d.motor = it->second;
  d.motor_count = static_cast<int>(drive.integer("count", 1, 16));
  d.gearing = drive.number("gearing", kPositive);
  d.kS_volts = drive.number("kS_volts", kNonNegative);
  d.voltage_limit_volts = drive.number("voltage_limit_volts", Bounds{0.0, d.motor.nominal_voltage_volts * 2.0, true});
  d.current_limit_amps = drive.number("current_limit_amps", Bounds{0.0, d.motor.stall_current_amps, true});
  d.velocity_limit = drive.optionalNumber("velocity_limit", kPositive);
  d.acceleration_limit = drive.optionalNumber("acceleration_limit", kPositive);
}

planner::DriveParams readFeedforward(TableReader& drive, const std::map<std::string, planner::MotorParams>& motors) {
  planner::DriveParams d;
  readMotors(drive, motors, d);
  d.gravity = gravityModel(drive);
  d.kG_volts = drive.number("kG_volts");
  d.kV = drive.number("kV", kPositive);
  d.kA = drive.number("kA", kPositive);
  // The mechanism must be able to hold itself against gravity within both limits.
  if (std::abs(d.kS_volts) + std::abs(d.kG_volts) >= d.voltage_limit_volts) {
    drive.fail("voltage_limit_volts", "must exceed kS_volts + |kG_volts| or the joint cannot hold against gravity");
  }
  if ((std::abs(d.kS_volts) + std::abs(d.kG_volts)) / d.motor.resistanceOhms() >= d.current_limit_amps) {
    drive.fail("current_limit_amps", "too small to hold the joint against gravity (kG / R)");
  }
  return d;
}

}  // namespace

planner::LinkInertia readInertia(TableReader& table, std::optional<planner::Point2> piece_cg_m) {
  planner::LinkInertia body;
  body.mass_kg = table.number("mass_kg", kNonNegative);
  if (piece_cg_m && !table.has("cg_m")) {
    body.cg_m = *piece_cg_m;
  } else {
    // A number is the distance along the link's x axis; [x, y] a point of the link frame.
    body.cg_m = table.isArray("cg_m") ? table.vector2("cg_m") : planner::Point2(table.number("cg_m"), 0.0);
  }
  // A piece is small beside its distance from the axis: a point mass unless the file says more.
  // A link's own inertia is not, so a drive must give it (0 would understate its torque).
  const bool piece = piece_cg_m.has_value();
  body.moi_kgm2 = piece && !table.has("moi_kgm2") ? 0.0 : table.number("moi_kgm2", kNonNegative);
  return body;
}

void readDrives(TableReader motor_table, TableReader drives, planner::RobotModel& robot) {
  std::map<std::string, planner::MotorParams> motors;
  for (const std::string& name : motor_table.keys()) motors.emplace(name, readMotor(motor_table.table(name)));
  if (motors.empty()) motor_table.fail("", "define at least one motor");
  motor_table.finish();
  robot.drives = planner::PerJoint<planner::DriveParams>(robot.jointCount());
  robot.bodies = planner::PerJoint<planner::LinkInertia>(robot.jointCount());
  for (int j = 0; j < robot.jointCount(); ++j) {
    const std::string& joint = robot.joints[j].name;
    if (!drives.has(joint)) drives.fail(joint, "missing: every joint needs a drive, keyed by its name");
    TableReader drive = drives.table(joint);
    const planner::DriveKind kind = driveKind(drive);
    if (j == 0) robot.drive_kind = kind;
    if (kind != robot.drive_kind) drive.fail("kind", "every joint's drive must be of the same kind");
    if (kind == planner::DriveKind::kFeedforward) {
      robot.drives[j] = readFeedforward(drive, motors);
    } else {
      readMotors(drive, motors, robot.drives[j]);
      robot.bodies[j] = readInertia(drive, std::nullopt);
    }
    drive.finish();
  }
  drives.finish();
}

}  // namespace cyber::config::detail

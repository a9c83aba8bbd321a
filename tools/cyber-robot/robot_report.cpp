#include "robot_report.hpp"

#include <fmt/format.h>

namespace cyber::tools {
namespace {

const char* mark(Severity severity) {
  switch (severity) {
    case Severity::kError: return "ERROR ";
    case Severity::kWarning: return "warn  ";
    case Severity::kOk: break;
  }
  return "      ";
}

// "(0.100, 1.571)": a pose's values in chain order.
std::string poseText(const planner::JointVector& q) {
  std::string out;
  for (Eigen::Index j = 0; j < q.size(); ++j) out += fmt::format("{}{:.3f}", j == 0 ? "" : ", ", q[j]);
  return "(" + out + ")";
}

std::string jointsText(const planner::RobotModel& robot) {
  std::string out;
  for (const planner::ChainJoint& joint : robot.joints) {
    out += fmt::format("{}{} {} [{:g}, {:g}] {}", out.empty() ? "" : ", ", joint.name,
                       joint.type == planner::JointType::kPrismatic ? "prismatic" : "revolute", joint.range.min,
                       joint.range.max, planner::unitName(joint.type));
  }
  return out;
}

std::string posesText(const planner::RobotModel& robot, const RobotCheck& check) {
  std::string out = fmt::format(
      "Named poses: distance to each scene at offset 0 (worst over its offset range); the clearance is "
      "{:.3f} m\n",
      robot.clearance_m);
  for (const PoseClearance& p : check.poses) {
    out += fmt::format("  {}[poses.{}] {:<12} {:<12} {:7.3f} m ({:.3f} m){}\n", mark(p.severity), p.pose_set, p.pose,
                       p.scene, p.clearance_m, p.worst_over_range_m,
                       p.clearance_m < robot.clearance_m ? " closer than the clearance to " + p.closest : "");
  }
  return out;
}

std::string reachText(const RobotCheck& check) {
  std::string out = "Moves between named poses, planned in the default scene at offset 0:\n";
  for (const PoseSetReach& r : check.reach) {
    const int pairs = r.poses * (r.poses - 1);
    out += fmt::format("  {}[poses.{}] {} of {} ordered pairs plan\n", r.refused.empty() ? "      " : "warn  ",
                       r.pose_set, r.pairs_planned, pairs);
    for (const RefusedPair& refused : r.refused) {
      out += fmt::format("          refused {} -> {}: {}\n", refused.from, refused.to, refused.reason);
    }
    if (r.groups.size() > 1) {
      std::string groups;
      for (const auto& group : r.groups) groups += fmt::format(" {{{}}}", fmt::join(group, ", "));
      out += "          poses joined both ways:" + groups + "\n";
    }
  }
  return out;
}

std::string drivesText(const RobotCheck& check) {
  std::string out = fmt::format("Drives with the heaviest held set ({}), each joint alone from rest over its range:\n",
                                check.heaviest_set);
  for (const DriveCheck& d : check.drives) {
    const std::string current =
        d.current_limit_amps > 0.0 ? fmt::format(" of {:.0f} A", d.current_limit_amps) : std::string(" (no limit)");
    out += fmt::format("  {}{}: holds with at most {:.2f} V of {:.1f} V, {:.1f} A per motor{}; ", mark(d.severity),
                       d.joint, d.hold_volts, d.voltage_limit_volts, d.hold_amps, current);
    if (d.severity == Severity::kError) {
      out += fmt::format("cannot hold or move both ways at {}\n", poseText(d.worst_q));
    } else {
      out += fmt::format("accelerates both ways at {:.2f} {}/s^2 or more\n", d.worst_acceleration, d.unit);
    }
  }
  return out;
}

// The planner settings a team would tune, each with where it came from; the daemon's and the
// solver's constants stay in docs/configuration.md.
std::string settingsText(const config::Config& config) {
  std::string out = "Planner settings (docs/configuration.md, \"Defaults\"):\n";
  for (const config::SettingOrigin& setting : config.settings) {
    if (setting.key.rfind("planner.", 0) != 0 || setting.source == config::SettingSource::kDefault) continue;
    out += fmt::format("        {} = {} ({})\n", setting.key, setting.value, config::sourceName(setting.source));
  }
  return out + fmt::format("        drives: {}\n",
                           config.robot.drive_kind == planner::DriveKind::kRigidBody ? "rigid body" : "feedforward");
}

// One line per error, naming what to change.
std::string errorsText(const planner::RobotModel& robot, const RobotCheck& check) {
  std::string out;
  for (const PoseClearance& p : check.poses) {
    if (p.severity != Severity::kError) continue;
    out += fmt::format(
        "error: pose [poses.{}] {} is {:.3f} m from {} in the default scene {}, closer than the clearance {:.3f} m: "
        "move the pose, or check that obstacle's outline\n",
        p.pose_set, p.pose, p.clearance_m, p.closest, p.scene, robot.clearance_m);
  }
  for (const DriveCheck& d : check.drives) {
    if (d.severity != Severity::kError) continue;
    out += fmt::format(
        "error: drive {} cannot hold its load or move both ways at {} with the heaviest held set "
        "({}): check [drives.{}] (gearing, count, current_limit_amps, voltage_limit_volts, mass_kg, kG_volts)\n",
        d.joint, poseText(d.worst_q), check.heaviest_set, d.joint);
  }
  return out;
}

}  // namespace

std::string robotReportText(const config::Config& config, const RobotCheck& check) {
  const planner::RobotModel& robot = config.robot;
  std::string out = fmt::format("Robot {}: {}; {} pieces, {} scenes (default {})\n\n", robot.name, jointsText(robot),
                                robot.pieces.size(), robot.scenes.size(), robot.scenes.front().name);
  out += posesText(robot, check) + "\n" + reachText(check) + "\n" + drivesText(check) + "\n" + settingsText(config);
  out += fmt::format("\n{} errors, {} warnings\n", check.count(Severity::kError), check.count(Severity::kWarning));
  out += errorsText(robot, check);
  return out;
}

}  // namespace cyber::tools

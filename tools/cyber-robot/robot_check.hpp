#pragma once
// `cyber-robot check`: what a team learns about its robot description before its first plan
// (docs/configuration.md, "Checking a robot"). Pure apart from planning: the report is values; the
// text is robot_report.hpp's.

#include <string>
#include <vector>

#include "cyber/config/load_config.hpp"
#include "cyber/planner.hpp"

namespace cyber::tools {

enum class Severity { kOk, kWarning, kError };

// One named pose in one scene: its distance to the scene at offset 0 and the smallest over the
// scene's offset range (the field elements swept over it).
struct PoseClearance {
  std::string pose_set;  // [poses.SET]
  std::string pose;
  std::string scene;
  double clearance_m = 0.0;         // at offset 0
  double worst_over_range_m = 0.0;  // over offset_range_m (the same when the scene does not move)
  std::string closest;              // the obstacle nearest at offset 0
  Severity severity = Severity::kOk;
};

// The ordered pairs of one pose set that the planner refuses in the default scene at offset 0.
struct RefusedPair {
  std::string from;
  std::string to;
  std::string reason;
};

struct PoseSetReach {
  std::string pose_set;
  int poses = 0;
  int pairs_planned = 0;
  std::vector<RefusedPair> refused;
  // Poses grouped so that any two in one group plan both ways (each group in file order).
  std::vector<std::vector<std::string>> groups;
};

// One joint's drive with the heaviest held set, over a grid of poses covering the joint ranges
// (49 per joint for one or two joints, 13 per joint for three), each joint driven alone from rest
// while the others hold still.
struct DriveCheck {
  std::string joint;
  std::string unit;         // m or rad
  double hold_volts = 0.0;  // largest |V| to hold still
  double hold_amps = 0.0;   // per motor, at that pose
  double voltage_limit_volts = 0.0;
  double current_limit_amps = 0.0;  // 0: none
  double worst_acceleration = 0.0;  // smallest of the fastest accelerations up and down (unit/s^2)
  planner::JointVector worst_q;     // where worst_acceleration is, one value per joint
  Severity severity = Severity::kOk;
};

struct RobotCheck {
  std::vector<PoseClearance> poses;
  std::vector<PoseSetReach> reach;
  std::string heaviest_set;
  std::vector<DriveCheck> drives;
  [[nodiscard]] int count(Severity severity) const;
};

// Poses per scene: closer than the clearance in the default scene at offset 0 is an error,
// elsewhere (another scene, another offset) a warning, since a pose may be meant for one field
// element only.
std::vector<PoseClearance> checkPoseClearances(const config::Config& config);
// Every ordered pair of each pose set planned in the default scene at offset 0.
std::vector<PoseSetReach> checkReach(const config::Config& config, const planner::MotionPlanner& planner);
// Poses per joint of the drive check's grid for a chain of `joint_count` joints: 49 for one or two,
// 13 for three (13^3 poses, within the 49^2 of two).
int driveSamplesPerJoint(int joint_count);
// An error when a joint cannot hold still or cannot accelerate both ways somewhere in its range.
std::vector<DriveCheck> checkDrives(const planner::RobotModel& robot, planner::HeldPieces heaviest);
// The held set of largest total mass (all pieces when they have mass data).
planner::HeldPieces heaviestPieces(const planner::RobotModel& robot);

}  // namespace cyber::tools

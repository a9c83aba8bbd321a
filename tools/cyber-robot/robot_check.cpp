#include "robot_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace cyber::tools {
namespace {

using planner::JointVector;

Severity poseSeverity(bool default_scene, double clearance_m, double worst_m, double required_m) {
  if (clearance_m < required_m) return default_scene ? Severity::kError : Severity::kWarning;
  return worst_m < required_m ? Severity::kWarning : Severity::kOk;
}

std::string obstacleName(const planner::Scene& scene, const planner::CollisionWorld& world, const JointVector& q) {
  // The world's obstacles are the scene's field elements, then its fixed ones (collision_world.hpp).
  const int index = world.distance(q).obstacle;
  const auto field = static_cast<int>(scene.obstacles.size());
  if (index < 0) return "";
  if (index < field) return scene.obstacles[static_cast<size_t>(index)].name;
  const auto fixed = static_cast<size_t>(index - field);
  return fixed < scene.fixed.size() ? scene.fixed[fixed].name : "";
}

// Connected components of the poses under "plans both ways".
std::vector<std::vector<std::string>> mutualGroups(const config::PoseSet& set,
                                                   const std::vector<std::vector<bool>>& plans) {
  const size_t n = set.poses.size();
  std::vector<size_t> group(n);
  std::iota(group.begin(), group.end(), size_t{0});
  const auto root = [&](size_t i) {
    while (group[i] != i) i = group[i];
    return i;
  };
  for (size_t a = 0; a < n; ++a) {
    for (size_t b = a + 1; b < n; ++b) {
      if (plans[a][b] && plans[b][a]) group[root(b)] = root(a);
    }
  }
  std::vector<std::vector<std::string>> groups;
  std::vector<int> slot(n, -1);
  for (size_t i = 0; i < n; ++i) {
    const size_t r = root(i);
    if (slot[r] < 0) {
      slot[r] = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[static_cast<size_t>(slot[r])].push_back(set.poses[i].name);
  }
  return groups;
}

// Every pose of a grid over the joint ranges, in joint 0's order first.
std::vector<JointVector> rangeGrid(const planner::RobotModel& robot) {
  const int samples = driveSamplesPerJoint(robot.jointCount());
  std::vector<JointVector> poses{JointVector::Zero(robot.jointCount())};
  for (int j = 0; j < robot.jointCount(); ++j) {
    const planner::JointRange& r = robot.range(j);
    std::vector<JointVector> next;
    for (const JointVector& q : poses) {
      for (int k = 0; k < samples; ++k) {
        JointVector p = q;
        p[j] = r.min + (r.max - r.min) * k / (samples - 1);
        next.push_back(p);
      }
    }
    poses = std::move(next);
  }
  return poses;
}

// The largest voltage joint j may apply: its voltage limit, or less when its current limit binds
// at rest (the current is affine in the voltage there).
double usableVolts(const planner::DriveModel& drives, int j) {
  const planner::DriveParams& d = drives.drive(j);
  const JointVector zero = JointVector::Zero(drives.jointCount());
  const double amps_per_volt =
      drives.amps(JointVector::Unit(drives.jointCount(), j), zero)[j] - drives.amps(zero, zero)[j];
  double volts = d.voltage_limit_volts;
  if (d.current_limit_amps > 0.0 && amps_per_volt > 0.0) volts = std::min(volts, d.current_limit_amps / amps_per_volt);
  return volts;
}

void checkDriveAt(const planner::DriveModel& drives, int j, const JointVector& q, double usable, DriveCheck& out) {
  const JointVector zero = JointVector::Zero(drives.jointCount());
  const JointVector unit = JointVector::Unit(drives.jointCount(), j);
  const double hold = drives.volts(q, zero, zero)[j];
  // At rest the voltage is affine in the acceleration (chain.hpp, PathVoltage).
  const double per_accel = drives.volts(q, zero, unit)[j] - hold;
  const double up = per_accel > 0.0 ? (usable - hold) / per_accel : -std::numeric_limits<double>::infinity();
  const double down = per_accel > 0.0 ? (usable + hold) / per_accel : -std::numeric_limits<double>::infinity();
  const double accel = std::min(up, down);
  if (std::abs(hold) > out.hold_volts) {
    out.hold_volts = std::abs(hold);
    out.hold_amps = std::abs(drives.amps(unit * hold, zero)[j]);
  }
  if (accel < out.worst_acceleration) {
    out.worst_acceleration = accel;
    out.worst_q = q;
  }
}

}  // namespace

// Joint limits included (docs/configuration.md, "Checking a robot"). One or two joints: 49, fine
// enough that a load's worst angle (a cosine's peak) over a range of a turn is missed by at most a
// 1 - cos(pi / 48) = 0.2 % underestimate. Three joints: 13, so that the grid's 13^3 = 2197 poses
// stay within the 49^2 = 2401 of two (the same miss is then at most 1 - cos(pi / 12) = 3.4 % over
// a turn, 1.4 % over a 4 rad wrist). Odd counts sample each range's middle.
int driveSamplesPerJoint(int joint_count) { return joint_count <= 2 ? 49 : 13; }

int RobotCheck::count(Severity severity) const {
  int n = 0;
  for (const PoseClearance& p : poses) n += p.severity == severity ? 1 : 0;
  for (const DriveCheck& d : drives) n += d.severity == severity ? 1 : 0;
  if (severity == Severity::kWarning) {
    for (const PoseSetReach& r : reach) n += r.refused.empty() ? 0 : 1;
  }
  return n;
}

std::vector<PoseClearance> checkPoseClearances(const config::Config& config) {
  const planner::RobotModel& robot = config.robot;
  std::vector<PoseClearance> out;
  for (const config::PoseSet& set : config.poses) {
    for (size_t s = 0; s < robot.scenes.size(); ++s) {
      const planner::Scene& scene = robot.scenes[s];
      const planner::CollisionWorld at_zero(robot, scene, set.pieces, 0.0);
      const planner::CollisionWorld swept(robot, scene, set.pieces, scene.offset_range_m);
      for (const config::NamedPose& pose : set.poses) {
        PoseClearance c;
        c.pose_set = set.name;
        c.pose = pose.name;
        c.scene = scene.name;
        c.clearance_m = at_zero.distance(pose.q).value;
        c.worst_over_range_m = std::min(c.clearance_m, swept.distance(pose.q).value);
        c.closest = obstacleName(scene, at_zero, pose.q);
        c.severity = poseSeverity(s == 0, c.clearance_m, c.worst_over_range_m, robot.clearance_m);
        out.push_back(std::move(c));
      }
    }
  }
  return out;
}

std::vector<PoseSetReach> checkReach(const config::Config& config, const planner::MotionPlanner& planner) {
  std::vector<PoseSetReach> out;
  for (const config::PoseSet& set : config.poses) {
    PoseSetReach reach;
    reach.pose_set = set.name;
    reach.poses = static_cast<int>(set.poses.size());
    const size_t n = set.poses.size();
    std::vector<std::vector<bool>> plans(n, std::vector<bool>(n, true));
    for (size_t a = 0; a < n; ++a) {
      for (size_t b = 0; b < n; ++b) {
        if (a == b) continue;
        planner::PlanRequest request;
        request.start = set.poses[a].q;
        request.goal = set.poses[b].q;
        request.pieces = set.pieces;
        const auto plan = planner.plan(request);
        if (plan) {
          ++reach.pairs_planned;
        } else {
          plans[a][b] = false;
          reach.refused.push_back({set.poses[a].name, set.poses[b].name, plan.error().message});
        }
      }
    }
    reach.groups = mutualGroups(set, plans);
    out.push_back(std::move(reach));
  }
  return out;
}

planner::HeldPieces heaviestPieces(const planner::RobotModel& robot) {
  planner::HeldPieces best;
  double best_kg = 0.0;
  for (int i = 0; i < robot.pieceSetCount(); ++i) {
    const planner::HeldPieces held = planner::HeldPieces::fromIndex(i);
    double kg = 0.0;
    for (size_t p = 0; p < robot.piece_inertias.size(); ++p) {
      if (held.holds(static_cast<int>(p))) kg += robot.piece_inertias[p].mass_kg;
    }
    if (kg > best_kg) {
      best_kg = kg;
      best = held;
    }
  }
  return best;
}

std::vector<DriveCheck> checkDrives(const planner::RobotModel& robot, planner::HeldPieces heaviest) {
  const planner::DriveModel drives = robot.driveModel(heaviest);
  const std::vector<JointVector> grid = rangeGrid(robot);
  std::vector<DriveCheck> out;
  for (int j = 0; j < drives.jointCount(); ++j) {
    const planner::DriveParams& d = drives.drive(j);
    const planner::ChainJoint& joint = robot.joints[j];
    DriveCheck check;
    check.joint = joint.name;
    check.unit = planner::unitName(joint.type);
    check.voltage_limit_volts = d.voltage_limit_volts;
    check.current_limit_amps = d.current_limit_amps;
    check.worst_acceleration = std::numeric_limits<double>::infinity();
    const double usable = usableVolts(drives, j);
    for (const JointVector& q : grid) checkDriveAt(drives, j, q, usable, check);
    check.severity = check.worst_acceleration > 0.0 ? Severity::kOk : Severity::kError;
    out.push_back(std::move(check));
  }
  return out;
}

}  // namespace cyber::tools

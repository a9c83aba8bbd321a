#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cyber/planner.hpp"
#include "cyber/plot/trajectory_plot.hpp"

namespace cyber::plot {
namespace {

using planner::JointVector;

// The centre of cell i of `cells` over a range.
double cellCentre(const planner::JointRange& r, int i, int cells) {
  return r.min + (i + 0.5) * ((r.max - r.min) / cells);
}

// Only whether d < clearance matters, so the distance may stop early at that cutoff.
bool blockedAt(const planner::RobotModel& robot, const planner::CollisionWorld& world, const JointVector& q) {
  return world.distance(q, robot.clearance_m).value < robot.clearance_m;
}

// A map of joints[0] (rows) and joints[1] (columns; -1 for a strip) with the other joints at
// `held`, or with `projected` sampled over its range when it is >= 0.
CSpaceMap sampleMap(const planner::RobotModel& robot, const planner::CollisionWorld& world, std::array<int, 2> joints,
                    const JointVector& held, int projected, int cells) {
  CSpaceMap map;
  map.joints = joints;
  map.held = held;
  map.projected_joint = projected;
  map.cells = {cells, joints[1] < 0 ? 1 : cells};
  map.blocked.assign(static_cast<size_t>(map.cells[0] * map.cells[1]), kFree);
  JointVector q = held;
  for (int i = 0; i < map.cells[0]; ++i) {
    q[joints[0]] = cellCentre(robot.range(joints[0]), i, map.cells[0]);
    for (int j = 0; j < map.cells[1]; ++j) {
      if (joints[1] >= 0) q[joints[1]] = cellCentre(robot.range(joints[1]), j, map.cells[1]);
      uint8_t& cell = map.blocked[static_cast<size_t>(i * map.cells[1] + j)];
      if (projected < 0) {
        cell = blockedAt(robot, world, q) ? kBlocked : kFree;
        continue;
      }
      // The projected joint's range ends included: a pose at a hard stop is a pose the chain takes.
      const planner::JointRange& r = robot.range(projected);
      int blocked = 0;
      for (int k = 0; k < kProjectionSamples; ++k) {
        q[projected] = r.min + (r.max - r.min) * k / (kProjectionSamples - 1);
        blocked += blockedAt(robot, world, q) ? 1 : 0;
        if (blocked > 0 && blocked <= k) break;  // some free, some not: nothing more to learn
      }
      cell = blocked == 0 ? kFree : (blocked == kProjectionSamples ? kBlocked : kSomeBlocked);
    }
  }
  return map;
}

}  // namespace

std::vector<JointAxis> jointAxes(const planner::RobotModel& robot) {
  std::vector<JointAxis> axes;
  for (int j = 0; j < robot.jointCount(); ++j) {
    const planner::ChainJoint& joint = robot.joints[j];
    const planner::DriveParams& drive = robot.drive(j);
    axes.push_back(JointAxis{joint.name, planner::unitName(joint.type), joint.range, drive.voltage_limit_volts,
                             drive.current_limit_amps});
  }
  return axes;
}

CSpaceView sampleCSpace(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces,
                        const std::vector<double>& third_joint_values, int cells) {
  CSpaceView view;
  view.joints = jointAxes(robot);
  const int n = robot.jointCount();
  const std::array<int, 2> joints{0, n >= 2 ? 1 : -1};
  if (scene < 0 || scene >= static_cast<int>(robot.scenes.size()) || cells < 2 || n < 1 || n > 3) {
    CSpaceMap empty;
    empty.joints = joints;
    if (n >= 1 && n <= planner::kMaxJoints) empty.held = JointVector::Zero(n);
    view.maps.push_back(empty);
    return view;
  }
  const planner::CollisionWorld world(robot, robot.scenes[static_cast<size_t>(scene)], pieces);
  const JointVector centre = JointVector::Zero(n);
  if (n < 3) {
    view.maps.push_back(sampleMap(robot, world, joints, centre, -1, cells));
    return view;
  }
  const JointAxis& third = view.joints[2];
  if (third_joint_values.empty()) {
    // Each cell takes up to kProjectionSamples distances: half the cells per joint keeps the
    // projection within a few times one slice's work.
    CSpaceMap map = sampleMap(robot, world, joints, centre, 2, std::max(2, cells / 2));
    map.caption = fmt::format("{} projected out", third.name);
    view.maps.push_back(std::move(map));
    return view;
  }
  for (double value : third_joint_values) {
    JointVector held = centre;
    held[2] = value;
    CSpaceMap map = sampleMap(robot, world, joints, held, -1, cells);
    map.caption = fmt::format("{} = {:.3f} {}", third.name, value, third.unit);
    view.maps.push_back(std::move(map));
  }
  return view;
}

void addRobotView(TrajectoryPlotData& data, const planner::RobotModel& robot, int scene, planner::HeldPieces pieces) {
  std::vector<double> third;
  std::vector<std::string> which;
  if (robot.jointCount() == 3 && data.joints.size() == 3 && !data.joints[2].position.empty()) {
    const std::vector<double>& wrist = data.joints[2].position;
    third.push_back(wrist.front());
    which.emplace_back(wrist.back() == wrist.front() ? "start and the goal" : "start");
    if (wrist.back() != wrist.front()) {
      third.push_back(wrist.back());
      which.emplace_back("goal");
    }
  }
  data.cspace = sampleCSpace(robot, scene, pieces, third);
  for (size_t k = 0; k < which.size() && k < data.cspace.maps.size(); ++k) {
    data.cspace.maps[k].caption += " at the " + which[k];
  }
}

}  // namespace cyber::plot

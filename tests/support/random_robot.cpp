#include "random_robot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "cyber/config/derived_defaults.hpp"
#include "cyber/planner/collision_world.hpp"
#include "random_robot_chain.hpp"
#include "reference_model.hpp"

namespace cyber::test {

using namespace random_robot;
using planner::CollisionWorld;
using planner::HeldPieces;
using planner::JointVector;
using planner::Point2;

namespace {

// Poses drawn for each share of free space, and the least shares a robot must have: a robot whose
// arm fits almost nowhere is not one a team builds, and its moves would test the draw, not the
// planner.
constexpr int kShareSamples = 400;
constexpr double kMinFreeShare = 0.25;          // no piece, offset 0
constexpr double kMinFreeShareAnyWorld = 0.05;  // any held set at either end of the offsets
constexpr int kPosesPerSet = 5;
constexpr int kTriesPerPose = 300;
// Named poses keep this much more than the clearance, as the shipped robots' do.
constexpr double kPoseMarginM = 0.02;
constexpr int kMaxRedraws = 50;

// A floor, the robot body, and 1-3 field elements in front of it: blocks standing on the floor,
// bars hanging in the air, slanted branches; their offsets span up to 0.3 m, a few reach closer.
SceneDraw drawScene(Draws& d, double body_height_m) {
  SceneDraw scene;
  scene.fixed.push_back({"floor", box(-5.0, -1.0, 5.0, 0.0)});
  scene.fixed.push_back({"robot_body", box(-d.rounded(0.3, 0.45), 0.0, d.rounded(0.3, 0.45), body_height_m)});
  const int count = d.integer(1, 3);
  for (int e = 0; e < count; ++e) {
    const double x0 = d.rounded(0.45, 1.3), width = d.rounded(0.04, 0.4);
    const int kind = d.integer(0, 2);
    Polygon p;
    if (kind == 0) p = box(x0, 0.0, x0 + width, d.rounded(0.1, 1.4));
    if (kind == 1) {
      const double y0 = d.rounded(0.5, 1.7);
      p = box(x0, y0, x0 + width, y0 + d.rounded(0.03, 0.15));
    }
    if (kind == 2) {
      const double y0 = d.rounded(0.4, 1.5), rise = d.rounded(-0.25, 0.25), thick = d.rounded(0.03, 0.1);
      p = {Point2(x0, y0), Point2(tidy(x0 + width), tidy(y0 + rise)), Point2(tidy(x0 + width), tidy(y0 + rise + thick)),
           Point2(x0, tidy(y0 + thick))};
    }
    scene.elements.push_back({fmt::format("element{}", e), std::move(p)});
  }
  if (d.chance(0.8)) scene.offset_range_m = {d.chance(0.25) ? -d.rounded(0.05, 0.1) : 0.0, d.rounded(0.1, 0.3)};
  return scene;
}

// The reference robot's [planner] settings, but for the two that depend on the mechanism's size:
// metric and grid step, from how fast a joint moves the robot's points (the point speed bound rho
// of CollisionWorld, m per m or per rad). A prismatic joint's metric is 1 and its step the
// reference's 0.02 m; a revolute joint's metric is (rho / 2)^2, the speed of the middle of what it
// turns squared (the reference's arm, rho 0.63 m, has its 0.1), and its step keeps a grid cell's
// motion of any point within 20 mm, never coarser than 0.02 rad.
// Issue 35: the loader now derives these when a file leaves them out (config::derivePlannerDefaults;
// docs/configuration.md, "Defaults derived from the robot"). To switch, write no metric, grid step
// or potential range in robotToml and drop this function.
// Robots of one and three joints take the loader's derivation, whose grid of a three-joint chain
// keeps to config::kGridMaxNodes (this one's would be tens of millions of nodes).
planner::PlannerSettings derivedSettings(const planner::RobotModel& model) {
  planner::PlannerSettings settings = referenceModel().planner;
  if (model.jointCount() != 2) {
    const config::DerivedPlannerDefaults derived = config::derivePlannerDefaults(model);
    settings.metric = derived.metric;
    settings.grid.step = derived.grid_step;
    settings.search.potential_range = derived.potential_range;
    return settings;
  }
  const CollisionWorld world(model, model.scenes.front(), model.allPieces());
  settings.metric.resize(model.jointCount());
  settings.grid.step.resize(model.jointCount());
  for (int j = 0; j < model.jointCount(); ++j) {
    const double rho_m = world.pointSpeedBound()[j];
    const bool prismatic = model.joints[static_cast<size_t>(j)].type == planner::JointType::kPrismatic;
    settings.metric[j] = prismatic ? 1.0 : std::round(0.25 * rho_m * rho_m * 1e4) / 1e4;
    settings.grid.step[j] = prismatic ? 0.02 : std::round(std::min(0.02, 0.02 / rho_m) * 1e5) / 1e5;
  }
  return settings;
}

JointVector uniformPose(Draws& d, const planner::RobotModel& model) {
  JointVector q(model.jointCount());
  for (int j = 0; j < model.jointCount(); ++j) q[j] = d.uniform(model.range(j).min, model.range(j).max);
  return q;
}

double freeShare(Draws& d, const planner::RobotModel& model, HeldPieces pieces, double offset_m) {
  const CollisionWorld world(model, model.scenes.front(), pieces, offset_m);
  int free = 0;
  for (int i = 0; i < kShareSamples; ++i) free += world.distance(uniformPose(d, model)).value >= model.clearance_m;
  return static_cast<double>(free) / kShareSamples;
}

// The [poses] section: kPosesPerSet poses for no piece and for each piece alone, each clear of the
// obstacles by kPoseMarginM more than the clearance; "" when a set has fewer than two.
std::string drawPoses(Draws& d, const planner::RobotModel& model) {
  std::string out;
  for (int set = 0; set <= static_cast<int>(model.pieces.size()); ++set) {
    const HeldPieces pieces = set == 0 ? HeldPieces{} : HeldPieces{}.with(set - 1);
    const CollisionWorld world(model, model.scenes.front(), pieces);
    std::string poses;
    int found = 0;
    for (int tries = 0; tries < kTriesPerPose * kPosesPerSet && found < kPosesPerSet; ++tries) {
      JointVector q = uniformPose(d, model);
      for (int j = 0; j < model.jointCount(); ++j) q[j] = std::round(q[j] * 1000.0) / 1000.0;
      if (!model.withinLimits(q) || world.distance(q).value < model.clearance_m + kPoseMarginM) continue;
      std::string pose;
      for (int j = 0; j < model.jointCount(); ++j) pose.append(j == 0 ? "" : ", ").append(fmt::format("{}", q[j]));
      poses.append(fmt::format("P{} = [{}]\n", found++, pose));
    }
    if (found < 2) return "";
    out.append(fmt::format("[poses.{}]\n{}\n", model.pieceSetName(pieces), poses));
  }
  return out;
}

bool roomy(Draws& d, const planner::RobotModel& model, double& share) {
  share = freeShare(d, model, HeldPieces{}, 0.0);
  if (share < kMinFreeShare) return false;
  const planner::JointRange offsets = model.scenes.front().offset_range_m;
  for (int set = 0; set < model.pieceSetCount(); ++set) {
    for (double offset_m : {offsets.min, offsets.max}) {
      if (freeShare(d, model, HeldPieces::fromIndex(set), offset_m) < kMinFreeShareAnyWorld) return false;
    }
  }
  return true;
}

RobotDraw drawRobot(Draws& d, unsigned seed, int joint_count) {
  RobotDraw robot;
  robot.name = fmt::format("random-robot-{}", seed);
  robot.clearance_m = d.rounded(0.02, 0.05);
  robot.rigid_body = d.chance(0.5);
  const double body_height_m = d.rounded(0.08, 0.25);
  robot.joints = drawChain(d, joint_count, body_height_m);
  robot.pieces = drawPieces(d, robot.joints.back());
  robot.drives = drawDrives(d, robot.joints, robot.pieces, robot.rigid_body);
  robot.scene = drawScene(d, body_height_m);
  robot.planner = referenceModel().planner;
  // One entry per joint, until derivedSettings replaces them from the loaded chain.
  robot.planner.metric = JointVector::Ones(joint_count);
  robot.planner.grid.step = JointVector::Constant(joint_count, 0.02);
  for (const JointDraw& j : robot.joints) {
    robot.summary.append(robot.summary.empty() ? "" : " + ")
        .append(j.type == planner::JointType::kPrismatic ? "prismatic" : "revolute");
  }
  robot.summary.append(fmt::format(", {} drives, {} piece(s), {} field element(s), offsets [{}, {}] m",
                                   robot.rigid_body ? "rigid-body" : "feedforward", robot.pieces.size(),
                                   robot.scene.elements.size(), robot.scene.offset_range_m.min,
                                   robot.scene.offset_range_m.max));
  return robot;
}

}  // namespace

int randomJointCount(unsigned seed) {
  // Seeds 1, 4, 7, ... two joints (the robots they drew when every robot had two), 2, 5, ... three,
  // 3, 6, ... one.
  return 1 + static_cast<int>(seed % 3);
}

RandomRobot randomRobot(unsigned seed) { return randomRobot(seed, randomJointCount(seed)); }

RandomRobot randomRobot(unsigned seed, int joint_count) {
  if (joint_count < 1 || joint_count > planner::kMaxJoints) {
    throw std::invalid_argument(
        fmt::format("the planner plans 1 to {} joints, not {}", planner::kMaxJoints, joint_count));
  }
  Draws d(seed);
  for (int draw = 0; draw < kMaxRedraws; ++draw) {
    RobotDraw robot = drawRobot(d, seed, joint_count);
    const std::string name = robot.name + ".toml";
    robot.planner = derivedSettings(config::parseConfig(robotToml(robot, ""), name).robot);
    RandomRobot out{seed, robotToml(robot, ""), config::parseConfig(robotToml(robot, ""), name), 0.0};
    if (!roomy(d, out.config.robot, out.free_share)) continue;
    const std::string poses = drawPoses(d, out.config.robot);
    if (poses.empty()) continue;
    out.toml = robotToml(robot, poses);
    out.config = config::parseConfig(out.toml, name);
    return out;
  }
  throw std::runtime_error(fmt::format("seed {}: no robot with room to move in {} draws", seed, kMaxRedraws));
}

bool saveRandomRobot(const RandomRobot& robot, const std::string& path, const std::string& trailer) {
  std::ofstream out(path);
  out << robot.toml << trailer;
  return static_cast<bool>(out);
}

}  // namespace cyber::test

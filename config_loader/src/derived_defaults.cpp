#include "cyber/config/derived_defaults.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace cyber::config {
namespace {

using planner::ChainJoint;
using planner::JointType;
using planner::Point2;
using planner::RobotModel;

// The loader's bounds of [planner.grid] step.
constexpr double kMinGridStep = 1e-4;
constexpr double kMaxGridStep = 0.5;

std::vector<Point2> verticesOn(const RobotModel& robot, int joint) {
  std::vector<Point2> out;
  auto add = [&](int on, const std::vector<planner::ConvexPolygon>& polygons) {
    if (on != joint) return;
    for (const planner::ConvexPolygon& p : polygons) out.insert(out.end(), p.vertices().begin(), p.vertices().end());
  };
  for (const auto& link : robot.links) add(link.joint, link.polygons);
  for (const auto& piece : robot.pieces) add(piece.joint, piece.polygons);
  return out;
}

// Samples of each joint between the one whose reach is measured and the one that carries the
// point, over its range (a three-joint chain's middle joint): the last joint's extremes are exact.
constexpr int kMiddleJointSamples = 256;

// The farthest a point v of the second joint's link comes from the first joint's axis. The
// distance is convex along a prismatic joint's travel, so its ends bound it; a revolute joint
// adds the angle at which v lines up with the second joint's origin.
double farthestOverSecondJoint(const ChainJoint& second, const Point2& v) {
  std::vector<double> qs{second.range.min, second.range.max};
  if (second.type == JointType::kRevolute) {
    const double aligned =
        std::atan2(second.origin_m.y(), second.origin_m.x()) - std::atan2(v.y(), v.x()) - second.axis_rad;
    const double turn = 2.0 * std::numbers::pi;
    // The range spans at most one turn, so at most two turns' copies of the angle lie in it.
    for (double q = aligned + turn * std::floor((second.range.min - aligned) / turn); q <= second.range.max;
         q += turn) {
      if (q >= second.range.min) qs.push_back(q);
    }
  }
  double farthest = 0.0;
  for (double q : qs) farthest = std::max(farthest, planner::childFrame({}, second, q).toWorld(v).norm());
  return farthest;
}

// The farthest a point v of link `link` comes from joint `joint`'s axis, over the ranges of the
// joints between: the joint just after exactly (farthestOverSecondJoint); with one joint between,
// that joint sampled and the last one exact in the frame the sample puts it in.
double farthestOverLaterJoints(const RobotModel& robot, int joint, int link, const Point2& v) {
  if (link == joint) return v.norm();
  if (link == joint + 1) return farthestOverSecondJoint(robot.joints[link], v);
  const ChainJoint& middle = robot.joints[joint + 1];
  double farthest = 0.0;
  for (int k = 0; k <= kMiddleJointSamples; ++k) {
    const double q = middle.range.min + (middle.range.max - middle.range.min) * k / kMiddleJointSamples;
    const planner::LinkFrame frame = planner::childFrame({}, middle, q);
    ChainJoint last = robot.joints[link];
    last.origin_m = frame.toWorld(last.origin_m);
    last.axis_rad += frame.angle_rad();
    farthest = std::max(farthest, farthestOverSecondJoint(last, v));
  }
  return farthest;
}

}  // namespace

double reach_m(const RobotModel& robot, int joint) {
  double farthest = kMinReach_m;
  for (int link = joint; link < robot.jointCount(); ++link) {
    for (const Point2& v : verticesOn(robot, link))
      farthest = std::max(farthest, farthestOverLaterJoints(robot, joint, link, v));
  }
  return farthest;
}

DerivedPlannerDefaults derivePlannerDefaults(const RobotModel& robot) {
  DerivedPlannerDefaults d;
  const int n = robot.jointCount();
  d.sweep_m_per_unit.resize(n);
  d.metric.resize(n);
  d.grid_step.resize(n);
  for (int j = 0; j < n; ++j) {
    const bool prismatic = robot.joints[j].type == JointType::kPrismatic;
    d.sweep_m_per_unit[j] = prismatic ? 1.0 : reach_m(robot, j);
  }
  const double heaviest = d.sweep_m_per_unit.maxCoeff();
  for (int j = 0; j < n; ++j) {
    const double weight = d.sweep_m_per_unit[j] / heaviest;
    d.metric[j] = weight * weight;
    const double span = robot.range(j).max - robot.range(j).min;
    const double step =
        std::clamp(robot.clearance_m / d.sweep_m_per_unit[j], span / kGridMaxCells, span / kGridMinCells);
    d.grid_step[j] = std::clamp(step, kMinGridStep, kMaxGridStep);
  }
  // A grid of more nodes than kGridMaxNodes (three joints) takes coarser steps, each joint's by the
  // same factor, so that a step still moves the robot about as far in every joint.
  double nodes = 1.0;
  for (int j = 0; j < n; ++j) nodes *= (robot.range(j).max - robot.range(j).min) / d.grid_step[j] + 1.0;
  if (n >= 3 && nodes > kGridMaxNodes) {
    const double coarser = std::pow(nodes / kGridMaxNodes, 1.0 / n);
    for (int j = 0; j < n; ++j) d.grid_step[j] = std::clamp(d.grid_step[j] * coarser, kMinGridStep, kMaxGridStep);
  }
  d.potential_range = std::max(kPotentialRangeClearances * robot.clearance_m, kMinPotentialRange_m) / heaviest;
  return d;
}

}  // namespace cyber::config

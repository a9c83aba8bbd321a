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

}  // namespace

double reach_m(const RobotModel& robot, int joint) {
  double farthest = kMinReach_m;
  for (const Point2& v : verticesOn(robot, joint)) farthest = std::max(farthest, v.norm());
  if (joint == 0) {
    for (const Point2& v : verticesOn(robot, 1))
      farthest = std::max(farthest, farthestOverSecondJoint(robot.joints[1], v));
  }
  return farthest;
}

DerivedPlannerDefaults derivePlannerDefaults(const RobotModel& robot) {
  DerivedPlannerDefaults d;
  for (int j = 0; j < planner::kJointCount; ++j) {
    const bool prismatic = robot.joints[static_cast<size_t>(j)].type == JointType::kPrismatic;
    d.sweep_m_per_unit[j] = prismatic ? 1.0 : reach_m(robot, j);
  }
  const double heaviest = d.sweep_m_per_unit.maxCoeff();
  for (int j = 0; j < planner::kJointCount; ++j) {
    const double weight = d.sweep_m_per_unit[j] / heaviest;
    d.metric[j] = weight * weight;
    const double span = robot.range(j).max - robot.range(j).min;
    const double step =
        std::clamp(robot.clearance_m / d.sweep_m_per_unit[j], span / kGridMaxCells, span / kGridMinCells);
    d.grid_step[j] = std::clamp(step, kMinGridStep, kMaxGridStep);
  }
  d.potential_range = std::max(kPotentialRangeClearances * robot.clearance_m, kMinPotentialRange_m) / heaviest;
  return d;
}

}  // namespace cyber::config

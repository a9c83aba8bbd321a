#pragma once
// The [planner] settings a robot description implies when its file leaves them out: pure
// functions of the parsed robot (docs/configuration.md, "Defaults derived from the robot").

#include "cyber/planner.hpp"

namespace cyber::config {

// A revolute joint that carries nothing farther from its axis than this counts as reaching this
// far, so that its metric weight stays positive and its grid step finite.
inline constexpr double kMinReach_m = 0.01;
// The grid's cells per joint range: at least kGridMinCells, so a short range still has room for a
// path around something, and at most kGridMaxCells, so that a small clearance or a long reach does
// not make every grid (one per scene, held set and band of offsets, built at start-up) too large.
// The shipped robots have 45 to 306 cells per joint.
inline constexpr int kGridMinCells = 20;
inline constexpr int kGridMaxCells = 400;
// At most this many nodes in one grid of a three-joint chain (about 40 per joint): at one clearance
// per step it would have millions, each built at start-up per scene, held set and band; the
// elevator-pivot-wrist's twelve grids build in about 2 s per scene on a 2-core machine at this
// budget and 5 s at four times it, with the same plans measured (docs/algorithm.md section 2.1).
inline constexpr double kGridMaxNodes = 65536.0;
// The potential decays over five clearances of the robot's motion (the shipped robots: 0.15 m
// with their 0.03 m clearance), and over at least kMinPotentialRange_m for a zero clearance.
inline constexpr double kPotentialRangeClearances = 5.0;
inline constexpr double kMinPotentialRange_m = 0.05;

struct DerivedPlannerDefaults {
  // How far the robot moves, at most, per unit of each joint [m per m or m per rad]: 1 for a
  // prismatic joint; for a revolute one the distance from its axis to the farthest point of the
  // links and game pieces it carries, over the range of the joints after it (its reach).
  planner::JointVector sweep_m_per_unit;
  // Sigma = diag((w_j / max w)^2): a step of any joint weighs the distance it moves the robot,
  // scaled so that the joint that moves it most has weight 1.
  planner::JointVector metric;
  // Per joint, the step that moves the robot by one clearance (a diagonal step of the search, by
  // two: no edge between two nodes that keep the clearance jumps over an obstacle), within
  // kGridMinCells to kGridMaxCells cells of its range.
  planner::JointVector grid_step;
  // kPotentialRangeClearances clearances of motion in the metric's units.
  double potential_range = 0.0;
};

// The farthest point of the links and pieces that joint `joint` carries from its axis [m]:
// the reach of a revolute joint (at least kMinReach_m).
double reach_m(const planner::RobotModel& robot, int joint);
// Every derived default of the robot: joints, links, pieces and clearance must be read.
DerivedPlannerDefaults derivePlannerDefaults(const planner::RobotModel& robot);

}  // namespace cyber::config

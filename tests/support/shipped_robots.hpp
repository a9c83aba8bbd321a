#pragma once
// The shipped robots (config/*.toml in the source tree) for tests: loaded, with their full
// planners, once per test binary; and what every plan of theirs must be.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cyber/config/load_config.hpp"
#include "cyber/planner/motion_planner.hpp"

namespace cyber::test {

struct ShippedRobot {
  config::Config config;
  planner::MotionPlanner planner;
};

// The configs tools/demo and the packages ship, by file name without ".toml": the three two-joint
// robots and the three-joint elevator-pivot-wrist (issue 34).
inline constexpr const char* kShippedRobotNames[] = {"reefscape-2025", "chargedup-2023-double-jointed",
                                                     "pivot-telescope", "reefscape-2025-elevator-pivot-wrist"};

// A shipped robot's name as a GoogleTest parameter name ('-' is not allowed there): for
// INSTANTIATE_TEST_SUITE_P over kShippedRobotNames.
std::string shippedRobotParamName(const ::testing::TestParamInfo<const char*>& info);

// A file of the source tree by its path from the tree's root (config/, tests/ data).
std::string sourceFile(const std::string& relative);

// config/NAME.toml with its planner (every scene, offset band and held set); a failure to load
// or plan aborts the test binary.
const ShippedRobot& shippedRobot(const std::string& name);

// Every ordered pair of distinct poses of each of the config's pose sets, with the set's pieces:
// the named moves of a robot, labelled "SET:FROM->TO".
struct NamedMove {
  std::string label;
  planner::PlanRequest request;
};
std::vector<NamedMove> namedMoves(const config::Config& config);

// The pose NAME of the config's pose set SET (a test failure when there is none).
planner::JointVector namedPose(const config::Config& config, const std::string& set, const std::string& name);

// Joint limits to 1e-9 (far inside the 1e-6 an external referee allows), clearance at the scene
// offset and the drive limits at every 1 ms sample and at the end; each column integrates to the
// one above it at samples `columns_step_s` apart (trapezoid), as an external referee checks a CSV
// with that spacing: within 1 % of the travel and 2 % of the peak speed.
void expectSound(const planner::RobotModel& model, const planner::Trajectory& trajectory, planner::HeldPieces pieces,
                 double offset_m, const std::string& label, double columns_step_s = 0.001);

// The fastest ride along the trajectory's own path is judged on samples this far apart: fine
// enough to resolve where the path's tangent goes to zero (the start and end at rest, a stop's
// turn), which a coarser ride passes faster than any motor could (docs/performance.md, "Seeded
// random moves on the three robots").
inline constexpr double kRideStepS = 1e-5;

// The trajectory's duration over the fastest ride along its own path (cyber/planner/trajectory.hpp), which
// must be within 1.02; a test failure (and 0) when there is no ride.
double expectNearTheFastestRide(const planner::Trajectory& trajectory, const std::string& label);

}  // namespace cyber::test

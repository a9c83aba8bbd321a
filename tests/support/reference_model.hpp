#pragma once
// The reference robot (config/reefscape-2025.toml, embedded in the binary) for tests.

#include "cyber/planner/path_planner.hpp"
#include "cyber/planner/robot_model.hpp"

namespace cyber::test {

// Loaded once from the embedded default configuration; aborts the test binary if it is invalid.
const planner::RobotModel& referenceModel();
// The path stage of its first scene (the reef); its grids are built once per test binary.
const planner::PathPlanner& referencePathPlanner();

}  // namespace cyber::test

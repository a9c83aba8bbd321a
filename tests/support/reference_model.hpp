#pragma once
// The reference robot (config/reefscape-2025.toml, embedded in the binary) for tests.

#include <string>

#include "cyber/planner/robot_model.hpp"
#include "path/path_planner.hpp"

namespace cyber::test {

// Loaded once from the embedded default configuration; aborts the test binary if it is invalid.
const planner::RobotModel& referenceModel();
// The path stage of its first scene (the reef); its grids are built once per test binary.
const planner::PathPlanner& referencePathPlanner();

// The reference robot's joints and pieces by the names its configuration gives them.
inline constexpr int kElevator = 0;
inline constexpr int kArm = 1;
// The held set named "none", a piece name, or names joined by '+' ("coral+algae"); aborts on an
// unknown name.
planner::HeldPieces referencePieces(const std::string& names);

}  // namespace cyber::test

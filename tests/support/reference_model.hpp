#pragma once
// The reference robot (config/reefscape-2025.toml, embedded in the binary) for tests.

#include "cyber/planner/robot_model.hpp"

namespace cyber::test {

// Loaded once from the embedded default configuration; aborts the test binary if it is invalid.
const planner::RobotModel& referenceModel();

}  // namespace cyber::test

#pragma once
// What a MotionPlanner built at create(): the robot and the path stage of every scene and band of
// offsets. Private to the planner (its units and the tests of its internals reach the path stage
// through drawnPathPlanner); the public header names only the type.

#include <vector>

#include "cyber/planner/motion_planner.hpp"
#include "path/path_planner.hpp"

namespace cyber::planner {

struct MotionPlanner::Scenes {
  RobotModel model;
  // By scene index: the scene as drawn, then one planner per band of offsets.
  std::vector<std::vector<PathPlanner>> path_planners;
};

// The path stage of a scene as drawn (offset 0; built unless a GridSelection left it out).
const PathPlanner& drawnPathPlanner(const MotionPlanner& planner, int scene);

}  // namespace cyber::planner

#include <algorithm>

#include "cyber/planner/collision_world.hpp"
#include "cyber/plot/trajectory_plot.hpp"

namespace cyber::plot {

CSpaceMap sampleCSpace(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces, int cells) {
  CSpaceMap map;
  map.elevator_m = robot.range(0);
  map.arm_rad = robot.range(1);
  if (scene < 0 || scene >= static_cast<int>(robot.scenes.size()) || cells < 2) return map;
  const planner::CollisionWorld world(robot, robot.scenes[static_cast<size_t>(scene)], pieces);
  map.elevator_cells = cells;
  map.arm_cells = cells;
  map.blocked.assign(static_cast<size_t>(cells * cells), 0);
  const double de = (map.elevator_m.max - map.elevator_m.min) / cells;
  const double da = (map.arm_rad.max - map.arm_rad.min) / cells;
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      const planner::JointVector q(map.elevator_m.min + (i + 0.5) * de, map.arm_rad.min + (j + 0.5) * da);
      // Only whether d < clearance matters, so the distance may stop early at that cutoff.
      const double d = world.distance(q, robot.clearance_m).value;
      map.blocked[static_cast<size_t>(i * cells + j)] = d < robot.clearance_m ? 1 : 0;
    }
  }
  return map;
}

}  // namespace cyber::plot

#include <algorithm>

#include "cyber/planner.hpp"
#include "cyber/plot/trajectory_plot.hpp"

namespace cyber::plot {

CSpaceMap sampleCSpace(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces, int cells) {
  CSpaceMap map;
  for (int k = 0; k < 2; ++k) {
    map.range[k] = robot.range(k);
    map.names[k] = robot.joints[static_cast<size_t>(k)].name;
    map.units[k] = planner::unitName(robot.joints[static_cast<size_t>(k)].type);
  }
  if (scene < 0 || scene >= static_cast<int>(robot.scenes.size()) || cells < 2) return map;
  const planner::CollisionWorld world(robot, robot.scenes[static_cast<size_t>(scene)], pieces);
  map.cells = {cells, cells};
  map.blocked.assign(static_cast<size_t>(cells * cells), 0);
  const double d0 = (map.range[0].max - map.range[0].min) / cells;
  const double d1 = (map.range[1].max - map.range[1].min) / cells;
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      const planner::JointVector q(map.range[0].min + (i + 0.5) * d0, map.range[1].min + (j + 0.5) * d1);
      // Only whether d < clearance matters, so the distance may stop early at that cutoff.
      const double d = world.distance(q, robot.clearance_m).value;
      map.blocked[static_cast<size_t>(i * cells + j)] = d < robot.clearance_m ? 1 : 0;
    }
  }
  return map;
}

}  // namespace cyber::plot

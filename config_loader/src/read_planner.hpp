#pragma once
// Reading [planner] (docs/configuration.md, "Planner"): every key optional. The metric, the grid
// step and the potential's range default to values derived from the robot, the rest to the
// constants of planner_settings.hpp.

#include <vector>

#include "cyber/config/setting_origin.hpp"
#include "cyber/planner.hpp"
#include "table_reader.hpp"

namespace cyber::config::detail {

// The robot's joints, links, pieces and clearance must be read already.
void readPlanner(TableReader planner, planner::RobotModel& robot, std::vector<SettingOrigin>& log);

}  // namespace cyber::config::detail

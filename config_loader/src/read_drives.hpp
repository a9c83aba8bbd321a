#pragma once
// Reading [motors.NAME] and [drives.JOINT] (docs/configuration.md).

#include "cyber/planner/robot_model.hpp"
#include "table_reader.hpp"

namespace cyber::config::detail {

// Both joints' drives, keyed by joint name, with the motors they name.
void readDrives(TableReader motors, TableReader drives, planner::RobotModel& robot);

}  // namespace cyber::config::detail

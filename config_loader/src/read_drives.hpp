#pragma once
// Reading [motors.NAME] and [drives.JOINT] (docs/configuration.md).

#include "cyber/planner.hpp"
#include "table_reader.hpp"

namespace cyber::config::detail {

// Mass data: mass_kg, and optionally cg_m (a distance along the link's x axis or [x, y]; default
// `default_cg_m`) and moi_kgm2 about the cg (default 0).
planner::LinkInertia readInertia(TableReader& table, const planner::Point2& default_cg_m);

// Both joints' drives, keyed by joint name, with the motors they name: all "feedforward" or all
// "rigid_body".
void readDrives(TableReader motors, TableReader drives, planner::RobotModel& robot);

}  // namespace cyber::config::detail

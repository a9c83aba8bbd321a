#pragma once
// Reading [motors.NAME] and [drives.JOINT] (docs/configuration.md).

#include <optional>

#include "cyber/planner.hpp"
#include "table_reader.hpp"

namespace cyber::config::detail {

// Mass data: mass_kg, cg_m (a distance along the link's x axis or [x, y]) and moi_kgm2 about the
// cg. A game piece's (`piece_cg_m` given) cg_m defaults to `piece_cg_m` and its moi_kgm2 to 0; a
// drive's link must give all three (docs/configuration.md, "Motors and drives").
planner::LinkInertia readInertia(TableReader& table, std::optional<planner::Point2> piece_cg_m);

// Both joints' drives, keyed by joint name, with the motors they name: all "feedforward" or all
// "rigid_body".
void readDrives(TableReader motors, TableReader drives, planner::RobotModel& robot);

}  // namespace cyber::config::detail

#pragma once
// Reading the mechanism and its world: [[joints]], [links.NAME], [pieces.NAME], [obstacles],
// [[scenes]] and [poses.SET] (docs/configuration.md).

#include <toml++/toml.h>

#include <vector>

#include "cyber/config/load_config.hpp"
#include "table_reader.hpp"

namespace cyber::config::detail {

// Fails with the new keys named when the file is in the format before chains (joints.elevator,
// joints.arm, [robot]).
void rejectOldFormat(const TableReader& root);
void readJoints(TableReader& root, planner::RobotModel& robot);
void readLinks(TableReader links, planner::RobotModel& robot);
void readPieces(TableReader pieces, planner::RobotModel& robot);
void readScenes(TableReader& root, TableReader obstacles, planner::RobotModel& robot);
std::vector<PoseSet> readPoses(TableReader poses, const planner::RobotModel& robot);

}  // namespace cyber::config::detail

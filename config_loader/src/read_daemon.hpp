#pragma once
// Reading [daemon] (docs/configuration.md, "Daemon"): the table and every key in it optional,
// with the defaults of daemon_settings.hpp; the device numbers default to 1..N in joint order and
// N + 1 for the status frame.

#include <vector>

#include "cyber/config/daemon_settings.hpp"
#include "cyber/config/setting_origin.hpp"
#include "cyber/planner.hpp"
#include "table_reader.hpp"

namespace cyber::config::detail {

DaemonSettings readDaemon(TableReader daemon, const planner::RobotModel& robot, std::vector<SettingOrigin>& log);

}  // namespace cyber::config::detail

#pragma once
// The text of `cyber-robot check` (robot_check.hpp): one section per check, errors and warnings
// marked at the start of their line so that a team can grep for them.

#include <string>

#include "cyber/config/load_config.hpp"
#include "robot_check.hpp"

namespace cyber::tools {

std::string robotReportText(const config::Config& config, const RobotCheck& check);

}  // namespace cyber::tools

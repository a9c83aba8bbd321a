#pragma once
// Where a trajectory to plot comes from: a cyber-plan CSV or an ARM_TRAJECTORY in an LCM log.

#include <cstdint>
#include <optional>
#include <string>

#include "cyber/plot/trajectory_plot.hpp"

namespace cyber::tools {

// Fills time and joint series from a CSV with cyber-plan's columns; sets `error` on failure.
bool readPlanCsv(const std::string& path, const planner::JointChain& joints, plot::TrajectoryPlotData& data,
                 std::string* error);

// Fills them from the last ARM_TRAJECTORY message on `channel` in an LCM log (or the one with
// `request_id`). The message carries volts, not amps: amps come from the drives' motor model.
bool readTrajectoryFromLog(const std::string& path, const std::string& channel, std::optional<int64_t> request_id,
                           const planner::RobotModel& robot, plot::TrajectoryPlotData& data, std::string* error);

}  // namespace cyber::tools

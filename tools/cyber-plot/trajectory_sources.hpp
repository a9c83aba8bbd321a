#pragma once
// Where a trajectory to plot comes from: a cyber-plan CSV or an ARM_TRAJECTORY in an LCM log.

#include <cstdint>
#include <optional>
#include <string>

#include "cyber/plot/trajectory_plot.hpp"
#include "cyber/result.hpp"

namespace cyber::tools {

// Why no trajectory came from a source; the message starts with the file's path.
enum class SourceStatus {
  kOk,
  kCannotOpen,    // the file cannot be opened
  kMalformed,     // a CSV without cyber-plan's columns for this robot, or a row that is not numbers
  kNoTrajectory,  // no samples, or no (matching) message on the channel
};

// The time and joint series of a CSV with cyber-plan's columns.
Result<plot::TrajectoryPlotData, SourceStatus> readPlanCsv(const std::string& path, const planner::JointChain& joints);

// The series and a title of the last ARM_TRAJECTORY message on `channel` in an LCM log (or the
// one with `request_id`). The message carries volts, not amps: amps come from the drives' motor
// model.
Result<plot::TrajectoryPlotData, SourceStatus> readTrajectoryFromLog(const std::string& path,
                                                                     const std::string& channel,
                                                                     std::optional<int64_t> request_id,
                                                                     const planner::RobotModel& robot);

}  // namespace cyber::tools

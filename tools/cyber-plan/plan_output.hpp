#pragma once
// What cyber-plan writes: the 1 ms CSV of design.md, the JSON summary, the plot.

#include <string>

#include "cyber/planner/motion_planner.hpp"
#include "cyber/plot/trajectory_csv.hpp"
#include "cyber/plot/trajectory_plot.hpp"
#include "plan_arguments.hpp"

namespace cyber::tools {

// Header (cyber/plot/trajectory_csv.hpp, with the joints' names) and one row per `step_s` (1 ms
// unless --csv-step says otherwise), plus the final sample at the exact duration.
bool writeTrajectoryCsv(const planner::Trajectory& trajectory, const planner::JointChain& joints,
                        const std::string& path, std::string* error, double step_s = kCsvStepS);

// One JSON object on one line.
std::string planSummaryJson(const planner::Plan& plan);

plot::TrajectoryPlotData plotDataOf(const planner::Plan& plan, const planner::RobotModel& robot, int scene,
                                    planner::HeldPieces pieces, const std::string& title);

}  // namespace cyber::tools

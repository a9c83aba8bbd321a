#pragma once
// What cyber-plan writes: the CSV of design.md (1 ms apart unless its columns need finer samples), the
// JSON summary, the plot.

#include <string>

#include "cyber/planner/motion_planner.hpp"
#include "cyber/planner/timed_plan.hpp"
#include "cyber/plot/trajectory_csv.hpp"
#include "cyber/plot/trajectory_plot.hpp"
#include "plan_arguments.hpp"

namespace cyber::tools {

// Header (cyber/plot/trajectory_csv.hpp, with the joints' names) and one row per `step_s` (1 ms
// unless --csv-step says otherwise), plus the final sample at the exact duration.
bool writeTrajectoryCsv(const planner::Trajectory& trajectory, const planner::JointChain& joints,
                        const std::string& path, std::string* error, double step_s = kCsvStepS);

// The widest of kCsvSteps at which the trajectory's columns agree as the planner judges them at
// 1 ms (MotionSettings' tolerances): 1 ms for every plan whose 1 ms columns agree. A plan whose
// columns agree at no step the planner can take is still the fastest, its columns the exact
// derivatives; on finer samples they agree (docs/moving-starts.md, "Consistent columns").
double csvStepFor(const planner::Trajectory& trajectory, const planner::MotionSettings& settings);

// One JSON object on one line.
std::string planSummaryJson(const planner::Plan& plan);

plot::TrajectoryPlotData plotDataOf(const planner::Plan& plan, const planner::RobotModel& robot, int scene,
                                    planner::HeldPieces pieces, const std::string& title);

}  // namespace cyber::tools

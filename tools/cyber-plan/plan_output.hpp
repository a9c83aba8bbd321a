#pragma once
// What cyber-plan writes: the CSV of design.md (1 ms apart unless finer samples are needed to
// describe the motion, csvSpacingFor), the JSON summary, the plot.

#include <string>

#include "cyber/planner.hpp"
#include "cyber/plot/trajectory_csv.hpp"
#include "cyber/plot/trajectory_plot.hpp"
#include "cyber/result.hpp"
#include "plan_arguments.hpp"

namespace cyber::tools {

// Why cyber-plan could not write an output; the message starts with the file's path.
enum class PlanOutputStatus { kOk, kCannotWrite };

// Header (cyber/plot/trajectory_csv.hpp, with the joints' names) and one row per `step_s` (1 ms
// unless --csv-step says otherwise), plus the final sample at the exact duration.
Result<Done, PlanOutputStatus> writeTrajectoryCsv(const planner::Trajectory& trajectory,
                                                  const planner::JointChain& joints, const std::string& path,
                                                  double step_s = kCsvStepS);

// Why a CSV's samples are closer than 1 ms: at 1 ms its columns would not integrate to each other
// (MotionSettings' tolerances), or a ride along its samples would be more than kCsvRideShare
// faster than the plan.
enum class FinerCsvReason { kNone, kColumns, kRide };

struct CsvSpacing {
  double step_s = kCsvStepS;
  FinerCsvReason reason = FinerCsvReason::kNone;
};

// The widest of kCsvSteps at which the trajectory's columns agree and its samples describe its
// path (kCsvRideShare), else the narrowest: 1 ms for every plan that 1 ms samples describe. A
// plan whose 1 ms samples do not is still the fastest, its columns the exact derivatives
// (docs/moving-starts.md, "Consistent columns" and "The CSV's spacing").
CsvSpacing csvSpacingFor(const planner::Trajectory& trajectory, const planner::MotionSettings& settings);

// What cyber-plan says on stderr about a CSV written finer than 1 ms.
std::string finerCsvMessage(const CsvSpacing& spacing);

// One JSON object on one line.
std::string planSummaryJson(const planner::Plan& plan);

plot::TrajectoryPlotData plotDataOf(const planner::Plan& plan, const planner::RobotModel& robot, int scene,
                                    planner::HeldPieces pieces, const std::string& title);

}  // namespace cyber::tools

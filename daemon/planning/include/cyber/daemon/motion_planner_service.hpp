#pragma once
// The daemon's PlanningService backed by the real planner (planner::MotionPlanner): its
// Trajectory becomes the streamer's SetpointSource.

#include <memory>

#include "cyber/daemon/planning_service.hpp"
#include "cyber/planner.hpp"

namespace cyber::daemon {

// Builds the planner (grids per game-piece set and scene) once, at start-up.
planner::Result<std::unique_ptr<PlanningService>> makeMotionPlannerService(const planner::RobotModel& robot);

}  // namespace cyber::daemon

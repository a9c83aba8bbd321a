#pragma once
// The daemon's PlanningService backed by the real planner (planner::MotionPlanner): its
// Trajectory becomes the streamer's SetpointSource.

#include <filesystem>
#include <memory>
#include <optional>

#include "cyber/daemon/planning_service.hpp"
#include "cyber/planner.hpp"

namespace cyber::daemon {

// Builds the planner (grids per game-piece set and scene) once, at start-up; with `cache_dir`,
// through the grid cache there (docs/design.md, "The grid cache").
planner::Result<std::unique_ptr<PlanningService>> makeMotionPlannerService(
    const planner::RobotModel& robot, const std::optional<std::filesystem::path>& cache_dir = std::nullopt);

}  // namespace cyber::daemon

#pragma once
// A picture of one planned move: the configuration space with the obstacle region and the path,
// and position, velocity, voltage and current of both joints against time with their limits.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "cyber/planner.hpp"
#include "cyber/plot/plot_status.hpp"
#include "cyber/result.hpp"

namespace cyber::plot {

// Joint 0 on the map's y axis, joint 1 on its x axis (for a cascade the carried joint reads across).
struct CSpaceMap {
  std::array<planner::JointRange, 2> range;
  std::array<std::string, 2> names;  // the config's joint names
  std::array<std::string, 2> units;  // "m" or "rad"
  std::array<int, 2> cells{};
  std::vector<uint8_t> blocked;  // joint-0-major: blocked[i * cells[1] + j]
};

// One joint signal per column of the cyber-plan CSV.
struct JointSeries {
  std::vector<double> position, velocity, volts, amps;
};

struct TrajectoryPlotData {
  std::string title;
  CSpaceMap cspace;
  std::vector<double> time_s;
  std::array<JointSeries, 2> joints;  // joint 0, joint 1 (names and units: cspace)
  std::array<double, 2> voltage_limit_volts{};
  std::array<double, 2> current_limit_amps{};
};

// The C-space map of a robot for a held-piece set, sampled on a grid of about `cells` per joint:
// a cell is blocked where the robot is closer than the clearance to an obstacle of `scene`.
CSpaceMap sampleCSpace(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces, int cells = 200);

// Writes the PNG; kCannotWrite when cairo cannot write the file.
Result<Done, PlotStatus> renderTrajectoryPng(const TrajectoryPlotData& data, const std::string& path);

}  // namespace cyber::plot

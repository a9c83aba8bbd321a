#pragma once
// A picture of one planned move: the configuration space with the obstacle region and the path,
// and position, velocity, voltage and current of both joints against time with their limits.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "cyber/planner/robot_model.hpp"

namespace cyber::plot {

struct CSpaceMap {
  planner::JointRange elevator_m;
  planner::JointRange arm_rad;
  int elevator_cells = 0;
  int arm_cells = 0;
  std::vector<uint8_t> blocked;  // elevator-major: blocked[i * arm_cells + j]
};

// One joint signal per column of the cyber-plan CSV.
struct JointSeries {
  std::vector<double> position, velocity, volts, amps;
};

struct TrajectoryPlotData {
  std::string title;
  CSpaceMap cspace;
  std::vector<double> time_s;
  std::array<JointSeries, 2> joints;  // elevator, arm
  std::array<double, 2> voltage_limit_volts{};
  std::array<double, 2> current_limit_amps{};
};

// The C-space map of a robot for a held-piece set, sampled on a grid of about `cells` per joint:
// a cell is blocked where the robot is closer than the clearance to an obstacle of `scene`.
CSpaceMap sampleCSpace(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces, int cells = 200);

// Writes the PNG; returns false with `error` set when cairo cannot write the file.
bool renderTrajectoryPng(const TrajectoryPlotData& data, const std::string& path, std::string* error);

}  // namespace cyber::plot

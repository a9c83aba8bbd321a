#pragma once
// A picture of one planned move: the configuration space with the obstacle region and the path,
// and position, velocity, voltage and current of every joint against time with their limits.
// The configuration space is drawn as the chain's joint count allows (docs/configuration.md,
// "Previewing a description"): one joint, its range over time with the blocked intervals; two,
// the plane of both; three, slices of the first two joints at the third joint's value at the
// move's start and at its goal, the whole path projected onto both.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "cyber/planner.hpp"
#include "cyber/plot/plot_status.hpp"
#include "cyber/result.hpp"

namespace cyber::plot {

// One joint of the picture: the config's name, its unit, its range and its drive's limits.
struct JointAxis {
  std::string name;
  std::string unit;  // "m" or "rad"
  planner::JointRange range;
  double voltage_limit_volts = 0.0;
  double current_limit_amps = 0.0;  // 0: none
};

// Every joint of `robot` in chain order.
std::vector<JointAxis> jointAxes(const planner::RobotModel& robot);

// One map of the configuration space: joint joints[0] on the map's y axis, joint joints[1] on its
// x axis (for a cascade the carried joint reads across), any other joint held at its value in
// `held`. A chain of one joint has a strip: joints[1] = -1 and cells[1] = 1.
struct CSpaceMap {
  std::array<int, 2> joints{0, 1};
  std::array<int, 2> cells{};
  // joints[0]-major: blocked[i * cells[1] + j]: kFree, kBlocked, or for a projection kSomeBlocked
  // where some but not every value of the joint projected out is closer than the clearance.
  std::vector<uint8_t> blocked;
  planner::JointVector held;  // the pose the other joints are held at (size N; the map's own entries unused)
  int projected_joint = -1;   // >= 0: the map projects this joint out instead of holding it
  std::string caption;        // what the map shows beyond its two joints ("" for two joints)
};
inline constexpr uint8_t kFree = 0;
inline constexpr uint8_t kBlocked = 1;
inline constexpr uint8_t kSomeBlocked = 2;

// The C-space of a robot for a held-piece set as the picture draws it.
struct CSpaceView {
  std::vector<JointAxis> joints;  // every joint, chain order
  std::vector<CSpaceMap> maps;    // one, or for three joints a slice per held value or a projection
};

// One joint signal per column of the cyber-plan CSV.
struct JointSeries {
  std::vector<double> position, velocity, volts, amps;
};

struct TrajectoryPlotData {
  std::string title;
  CSpaceView cspace;  // its joints name the series and give their limits
  std::vector<double> time_s;
  std::vector<JointSeries> joints;  // one per joint, chain order, each series as long as time_s
};

// The C-space view of a robot for a held-piece set, sampled on a grid of about `cells` per joint:
// a cell is blocked where the robot is closer than the clearance to an obstacle of `scene`. One
// joint: a strip of `cells`; two: one `cells` x `cells` map. Three: a slice of the first two
// joints at each value of `third_joint_values` (the poses' third joint), or, when there are none,
// their projection: blocked where no value of the third joint (sampled on kProjectionSamples
// values over its range) is free, some-blocked where some are not.
inline constexpr int kProjectionSamples = 25;
CSpaceView sampleCSpace(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces,
                        const std::vector<double>& third_joint_values = {}, int cells = 200);

// What the picture needs of the robot beside the samples already in `data`: the joints and the
// C-space view of `pieces` in `scene` (three joints: sliced at the third joint's value at the
// first and the last sample, once when they are the same).
void addRobotView(TrajectoryPlotData& data, const planner::RobotModel& robot, int scene, planner::HeldPieces pieces);

// Writes the PNG; kNothingToDraw when the data has not one series per joint of its view (1 to
// planner::kMaxJoints) each as long as its times, kCannotWrite when cairo cannot write the file.
Result<Done, PlotStatus> renderTrajectoryPng(const TrajectoryPlotData& data, const std::string& path);

}  // namespace cyber::plot

#pragma once
// The robot in the world, for a chain of any joint count: the side view of the scene (floor, reef,
// obstacles) with the robot's
// polygons and held pieces at a pose, a filmstrip and an animation of a planned move with its
// smallest clearance marked, and the preview of a robot description (docs/configuration.md,
// "Previewing a description").

#include <string>
#include <vector>

#include "cyber/planner.hpp"
#include "cyber/plot/trajectory_plot.hpp"

namespace cyber::plot {

struct NamedJointPose {
  std::string name;
  planner::JointVector q;
};

// Maps the world frame (m, y up) into a pixel box with one scale for both axes.
struct WorldCanvas {
  double box_x = 0, box_y = 0, box_w = 1, box_h = 1;  // px
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;              // world rectangle shown, m
  double scale = 1;                                   // px per m
  [[nodiscard]] double px(double x) const { return box_x + (x - x0) * scale; }
  [[nodiscard]] double py(double y) const { return box_y + box_h - (y - y0) * scale; }
};

// The rectangle every robot point can reach (the rail swept by the farthest robot point, pieces
// included, plus a margin), from just below the floor, centred in the box.
WorldCanvas fitWorld(const planner::RobotModel& robot, double box_x, double box_y, double box_w, double box_h);

// Colours of the world view, for the pixel checks of the tests.
struct WorldColors {
  uint8_t sky[3] = {246, 247, 252};
  uint8_t obstacle[3] = {110, 116, 130};
  uint8_t links[planner::kMaxJoints][3] = {{70, 110, 200}, {230, 115, 25}, {125, 85, 195}};  // by joint
  uint8_t pieces[4][3] = {{240, 236, 215}, {40, 170, 140}, {200, 60, 160}, {230, 200, 40}};  // by piece index
};
inline constexpr WorldColors kWorldColors{};

// The smallest clearance of a move: signed distance and closest points over its samples.
struct Clearance {
  double distance_m = 0;
  double time_s = 0;
  size_t sample = 0;
  planner::Point2 robot_point = planner::Point2::Zero(), obstacle_point = planner::Point2::Zero();
};

// The poses of a move at its sample times; every pose has one value per joint of the robot drawn.
struct Move {
  std::vector<double> time_s;
  std::vector<planner::JointVector> q;
};
Move moveOf(const TrajectoryPlotData& data);
Clearance smallestClearance(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces, const Move& move);

constexpr int kWorldWidth = 700;
constexpr int kWorldHeight = 900;

// Where renderWorldPng puts the world.
WorldCanvas worldPngCanvas(const planner::RobotModel& robot);
// One pose: the robot over its scene, kWorldWidth x kWorldHeight px. Like every picture here,
// kCannotWrite when the file cannot be written.
Result<Done, PlotStatus> renderWorldPng(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces,
                                        const planner::JointVector& q, const std::string& title,
                                        const std::string& path);
// `frames` poses at even times of the move side by side, the one nearest the smallest clearance
// moved to it and framed in red; kNothingToDraw for a move without samples or whose poses are not
// of the robot's joint count.
Result<Done, PlotStatus> renderFilmstripPng(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces,
                                            const Move& move, int frames, const std::string& title,
                                            const std::string& path);
// The move as an animated PNG (APNG) at `fps` (at most 200 frames), each frame with its closest
// pair in grey and the smallest clearance of the move in red; one frame is at that smallest.
// kNothingToDraw as for the filmstrip.
Result<Done, PlotStatus> renderAnimationApng(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces,
                                             const Move& move, int fps, const std::string& title,
                                             const std::string& path);
// A robot description at a glance: the robot at `poses` over the obstacles of `scene`, and the
// C-space view of `pieces` with the poses marked (sampleCSpace: for three joints the first two
// with the third projected out, since the poses hold the third at different values).
Result<Done, PlotStatus> renderConfigPreviewPng(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces,
                                                const std::vector<NamedJointPose>& poses, const std::string& title,
                                                const std::string& path);

}  // namespace cyber::plot

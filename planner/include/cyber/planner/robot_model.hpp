#pragma once
// The robot description the planner works on: joints, polygons, scenes, drives and settings.
// Plain values; the TOML loader (config_loader) fills and validates them.

#include <optional>
#include <string>
#include <vector>

#include "cyber/planner/convex_polygon.hpp"
#include "cyber/planner/joint_chain.hpp"
#include "cyber/planner/motor_params.hpp"
#include "cyber/planner/topp_al_settings.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

// The carriage rail: pivot(t) = base + t * (cos tilt, sin tilt)  (algorithm.md section 1).
struct Rail {
  Point2 base_m = Point2::Zero();
  double tilt_rad = 0.0;
};

// Robot polygons in the arm frame (x along the arm from the pivot).
struct RobotGeometry {
  std::vector<ConvexPolygon> arm;    // always present
  std::vector<ConvexPolygon> coral;  // added while coral is held
  std::vector<ConvexPolygon> algae;  // added while algae is held
};

struct NamedPolygon {
  std::string name;
  ConvexPolygon polygon;  // world frame
};

// A named set of obstacles; the first scene of a model is its default.
struct Scene {
  std::string name;
  std::vector<NamedPolygon> obstacles;
};

enum class GravityModel { kConstant, kCosine };  // elevator: g = 1; arm: g = cos(theta)

// One joint's drive: WPILib feedforward, the motors behind it and its limits.
// Joint units are m (elevator) or rad (arm); kV is V per unit/s, kA V per unit/s^2.
struct DriveParams {
  MotorParams motor;
  int motor_count = 1;
  double gearing = 1.0;  // motor rad per joint unit
  double kS_volts = 0.0;
  double kG_volts = 0.0;
  double kV = 0.0;
  double kA = 0.0;
  GravityModel gravity = GravityModel::kConstant;
  double voltage_limit_volts = 12.0;
  double current_limit_amps = 0.0;           // per motor
  std::optional<double> velocity_limit;      // joint units/s
  std::optional<double> acceleration_limit;  // joint units/s^2

  [[nodiscard]] double gravityFactor(double q) const;  // g(q) of algorithm.md section 3
  // Feedforward voltage V(q, qdot, qddot) and the per-motor current it draws.
  [[nodiscard]] double volts(double q, double qdot, double qddot) const;
  [[nodiscard]] double amps(double volts, double qdot) const;
};

struct GridSettings {
  double elevator_step_m = 0.02;
  double arm_step_rad = 0.02;
};

struct SearchSettings {
  double potential_weight = 2.0;  // weight of the potential in the A* step cost
  double potential_range = 0.15;  // weighted C-space distance over which the potential decays
};

// Eq. 8 weights for waypoints waypoint_spacing apart (the terms are plain sums, so the balance
// depends on the spacing). Tuned on the public moves: with w_p = 0.1, w_s = 10 the obstacle term
// dragged waypoints out of the reef's channels and bunched them (then the spline cut corners
// and fell back to the unsmoothed path), and L-BFGS needed ~40 iterations; these values keep the
// search's topology, halve the curvature integral and converge in ~4 iterations.
struct SmoothingSettings {
  double waypoint_spacing = 0.05;     // weighted C-space spacing of the optimised waypoints
  double obstacle_weight = 0.5;       // w_o  (eq. 8)
  double obstacle_decay_m = 0.03;     // d0   (eq. 8)
  double prior_weight = 20.0;         // w_p
  double length_weight = 1.0;         // w_l
  double smoothness_weight = 1000.0;  // w_s
  int max_iterations = 200;
  double gradient_tolerance = 1e-6;
  // L-BFGS also stops when a step lowers J by less than this fraction of max(1, |J|) (0: off).
  double relative_cost_tolerance = 1e-9;
  // With a start velocity v0 the path first runs straight along v0 for |v0|_Sigma * lead_in_time_s
  // (weighted length, at most max_lead_in), so a fast start does not meet a sharp bend at once.
  double lead_in_time_s = 0.1;
  double max_lead_in = 0.3;
};

struct ToppSettings {
  int grid_points = 200;                 // K
  double limit_check_step_s = 0.001;     // the continuous trajectory is checked at this step
  double limit_check_tolerance = 0.005;  // relative overshoot of a limit accepted at that check
  int max_limit_refinements = 8;         // re-solves with tightened limits after a failed check
  // Tolerances, caps and penalty schedule of the solver; [planner.topp] sets all but the L-BFGS ones.
  topp::AlSettings solver;
};

struct PlannerSettings {
  JointVector metric = JointVector(1.0, 0.1);  // diagonal of Sigma: |v|^2 = v' Sigma v
  GridSettings grid;
  SearchSettings search;
  SmoothingSettings smoothing;
  ToppSettings topp;
};

struct RobotModel {
  std::string name;
  JointRange elevator_range_m;
  JointRange arm_range_rad;
  Rail rail;
  RobotGeometry geometry;
  std::vector<Scene> scenes;  // scenes.front() is the default
  double clearance_m = 0.0;
  DriveParams elevator_drive;
  DriveParams arm_drive;
  PlannerSettings planner;

  [[nodiscard]] JointRange range(int joint) const { return joint == kElevator ? elevator_range_m : arm_range_rad; }
  [[nodiscard]] const DriveParams& drive(int joint) const { return joint == kElevator ? elevator_drive : arm_drive; }
  [[nodiscard]] bool withinLimits(const JointVector& q, double tolerance = 0.0) const {
    return elevator_range_m.contains(q[kElevator], tolerance) && arm_range_rad.contains(q[kArm], tolerance);
  }
  // Index of a scene by name; -1 when there is none.
  [[nodiscard]] int sceneIndex(const std::string& name) const;
};

}  // namespace cyber::planner

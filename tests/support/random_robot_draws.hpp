#pragma once
// What random_robot.cpp draws before it writes a description: a chain, its drives, its pieces and
// its scene, as plain values. The writer (random_robot_toml.cpp) turns them into the TOML of
// docs/configuration.md.

#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "cyber/planner/chain.hpp"
#include "cyber/planner/planner_settings.hpp"

namespace cyber::test::random_robot {

using Polygon = std::vector<planner::Point2>;

// Draws from a seed that give the same robot wherever the tests run: the engine's output is
// fixed by the standard, its distributions are not.
class Draws {
 public:
  explicit Draws(unsigned seed) : engine_(seed) {}
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(engine_()) / static_cast<double>(std::mt19937::max() + 1.0);
  }
  // Rounded to 1 / per_unit, so that the description reads as a person writes one and loads back
  // as drawn.
  double rounded(double lo, double hi, double per_unit = 1000.0) {
    return std::round(uniform(lo, hi) * per_unit) / per_unit;
  }
  int integer(int lo, int hi) { return lo + static_cast<int>(engine_() % static_cast<unsigned>(hi - lo + 1)); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }

 private:
  std::mt19937 engine_;
};

// A drawn figure's sum or difference to 0.1 mm (or 0.1 mrad), so that the description shows
// 0.416 where the arithmetic left 0.41600000000000004.
inline double tidy(double x) { return std::round(x * 1e4) / 1e4; }

inline Polygon box(double x0, double y0, double x1, double y1) {
  return {planner::Point2(tidy(x0), tidy(y0)), planner::Point2(tidy(x1), tidy(y0)), planner::Point2(tidy(x1), tidy(y1)),
          planner::Point2(tidy(x0), tidy(y1))};
}

// The figures WPILib's DCMotor gives a motor.
struct Motor {
  const char* key;
  double stall_torque_nm;
  double stall_current_amps;
  double free_current_amps;
  double free_speed_rpm;
};

struct Body {
  double mass_kg = 0.0;
  planner::Point2 cg_m = planner::Point2::Zero();  // link frame
  double moi_kgm2 = 0.0;
};

struct JointDraw {
  std::string name;
  planner::JointType type = planner::JointType::kRevolute;
  planner::Point2 origin_m = planner::Point2::Zero();
  double axis_deg = 0.0;
  planner::JointRange range;
  std::vector<Polygon> outline;  // link frame
  double tip_m = 0.0;            // along the link's x axis: where the next joint or the pieces sit
  Body body;
};

struct DriveDraw {
  const Motor* motor = nullptr;
  int count = 1;
  double gearing = 1.0;
  double kS_volts = 0.0;
  double voltage_limit_volts = 12.0;
  double current_limit_amps = 40.0;
  std::optional<double> velocity_limit;
  std::optional<double> acceleration_limit;
  // Feedforward only: what a team would derive from the mechanism (docs/configuration.md).
  const char* gravity = "none";
  double kG_volts = 0.0;
  double kV = 0.0;
  double kA = 0.0;
};

struct PieceDraw {
  std::string name;
  Polygon polygon;  // the last link's frame
  Body body;
};

struct NamedPolygonDraw {
  std::string name;
  Polygon polygon;  // world frame
};

struct SceneDraw {
  std::vector<NamedPolygonDraw> fixed;     // the floor and the robot body
  std::vector<NamedPolygonDraw> elements;  // 1-3 field elements
  planner::JointRange offset_range_m;
};

struct RobotDraw {
  std::string name;
  std::string summary;  // one line for a person: the mechanism in words
  double clearance_m = 0.03;
  bool rigid_body = false;
  std::vector<JointDraw> joints;
  std::vector<DriveDraw> drives;
  std::vector<PieceDraw> pieces;
  SceneDraw scene;
  planner::PlannerSettings planner;
};

// The description in the TOML of docs/configuration.md, with `poses` (a [poses] section, or
// empty) before the daemon's settings.
std::string robotToml(const RobotDraw& robot, const std::string& poses);

}  // namespace cyber::test::random_robot

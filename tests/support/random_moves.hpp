#pragma once
// Seeded moves on a random robot (random_robot.hpp), drawn as SeededMoveDraw draws them on a
// shipped robot: poses uniform in the limits or a named pose nudged by up to 3 % of each range,
// any held set, a third at one of three offsets across the scene's range, a quarter moving starts
// (the state at a random instant of a planned move). Unlike SeededMoveDraw its tries are bounded:
// nobody tuned the planner for these robots, and one may plan no leg at all.

#include <optional>
#include <random>

#include "cyber/planner/motion_planner.hpp"
#include "random_robot.hpp"

namespace cyber::test {

inline constexpr int kRandomMovesPerRobot = 20;
inline constexpr int kRandomMovingStartEvery = 4;  // a quarter
inline constexpr int kRandomOffsetEvery = 3;       // a third

class RandomMoveDraw {
 public:
  RandomMoveDraw(const RandomRobot& robot, const planner::MotionPlanner& planner, unsigned seed)
      : robot_(robot), model_(robot.config.robot), planner_(planner), random_(seed) {}

  // The request of move number `move` (0, 1, ...: the draws depend on the order of calls); nullopt
  // when no clear pose turned up. A moving start whose legs were all refused falls back to the
  // start of its last leg, at rest.
  std::optional<planner::PlanRequest> next(int move);

 private:
  int uniformInt(int max) { return std::uniform_int_distribution<int>(0, max)(random_); }
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random_); }
  // A pose at least the clearance from `world`; nullopt after many tries.
  std::optional<planner::JointVector> clearPose(const planner::CollisionWorld& world);

  const RandomRobot& robot_;
  const planner::RobotModel& model_;
  const planner::MotionPlanner& planner_;
  std::mt19937 random_;
};

}  // namespace cyber::test

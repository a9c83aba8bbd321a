#pragma once
// Seeded random moves on a shipped robot, drawn as a new user would try them: poses anywhere in
// the limits or near a named pose, any held set the config declares, a third with the scene
// shifted, a quarter moving starts (the state at a random instant of a planned move, to a new
// goal). One draw serves the soundness sweep (SeededRandomMoves) and the stored durations
// (PlanDurations), so both see the same moves.

#include <random>
#include <string>

#include "shipped_robots.hpp"

namespace cyber::test {

inline constexpr int kSeededMovesPerRobot = 50;
inline constexpr int kSeededMovingStartEvery = 4;  // a quarter
inline constexpr int kSeededOffsetEvery = 3;       // a third
inline constexpr unsigned kSeededMovesSeed = 24;

class SeededMoveDraw {
 public:
  SeededMoveDraw(const ShippedRobot& robot, unsigned seed) : robot_(robot), model_(robot.config.robot), random_(seed) {}

  // The request of move number `move` (0, 1, ...: the draws depend on the order of calls).
  planner::PlanRequest next(int move);

 private:
  int uniformInt(int max) { return std::uniform_int_distribution<int>(0, max)(random_); }
  // A pose at least the clearance from `world` (the planner leaves closer ones first:
  // docs/algorithm.md section 5).
  planner::JointVector clearPose(const planner::CollisionWorld& world);

  const ShippedRobot& robot_;
  const planner::RobotModel& model_;
  std::mt19937 random_;
};

// The move as cyber-plan's arguments, to reproduce it and hand it to the referee.
std::string cyberPlanArguments(const planner::PlanRequest& request);

}  // namespace cyber::test

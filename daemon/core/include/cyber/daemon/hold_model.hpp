#pragma once
// Hold setpoints: target position, zero velocity and the gravity feedforward kG*g(q) of each joint
// (WPILib feedforward at rest, algorithm.md section 3 with qdot = qddot = 0).

#include "cyber/daemon/setpoint_source.hpp"
#include "cyber/planner/robot_model.hpp"

namespace cyber::daemon {

class HoldModel {
 public:
  HoldModel(const planner::DriveParams& elevator, const planner::DriveParams& arm) : elevator_(elevator), arm_(arm) {}
  explicit HoldModel(const planner::RobotModel& robot) : HoldModel(robot.elevator_drive, robot.arm_drive) {}

  [[nodiscard]] JointSetpoints hold(const JointVector& q) const;

 private:
  planner::DriveParams elevator_;
  planner::DriveParams arm_;
};

}  // namespace cyber::daemon

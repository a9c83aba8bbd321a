#pragma once
// Hold setpoints: target position, zero velocity and the gravity feedforward of each joint (the
// drive model at rest, algorithm.md section 3 with qdot = qddot = 0).

#include "cyber/daemon/setpoint_source.hpp"
#include "cyber/planner.hpp"

namespace cyber::daemon {

class HoldModel {
 public:
  explicit HoldModel(const planner::DriveModel& drives) : drives_(drives) {}
  // Holds with nothing held: the gravity a held piece adds under rigid-body dynamics is left to
  // the controllers' feedback (docs/design.md).
  explicit HoldModel(const planner::RobotModel& robot) : HoldModel(robot.driveModel({})) {}

  [[nodiscard]] JointSetpoints hold(const JointVector& q) const;

 private:
  planner::DriveModel drives_;
};

}  // namespace cyber::daemon

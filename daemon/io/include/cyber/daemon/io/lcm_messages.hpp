#pragma once
// Conversions between the daemon's values and the cyberplanner LCM messages. Pure functions:
// times come in as parameters (LCM utime is wall-clock microseconds).

#include <cstdint>
#include <optional>

#include "cyber/daemon/cancel_request.hpp"
#include "cyber/daemon/goal_request.hpp"
#include "cyber/daemon/goal_status.hpp"
#include "cyber/daemon/io/streamer_thread.hpp"
#include "cyber/daemon/setpoint_source.hpp"
#include "cyber/planner.hpp"
#include "cyberplanner/arm_cancel_t.hpp"
#include "cyberplanner/arm_goal_t.hpp"
#include "cyberplanner/arm_plan_status_t.hpp"
#include "cyberplanner/arm_setpoint_t.hpp"
#include "cyberplanner/arm_state_t.hpp"
#include "cyberplanner/arm_trajectory_t.hpp"

namespace cyber::daemon::io {

std::int64_t wallMicros();

GoalRequest goalFromMessage(const cyberplanner::arm_goal_t& message);

// Nothing for an action that is not one of arm_cancel_t's ACTION_*.
std::optional<CancelRequest> cancelFromMessage(const cyberplanner::arm_cancel_t& message);

struct MeasuredState {
  JointVector q;
  JointVector qdot;
};
// Accepted when num_joints is the robot's joint count and the values are finite and within the joint ranges widened by
// `margin` (m or rad): a sensor a little past a limit is still the mechanism's position; nonsense is not held.
std::optional<MeasuredState> stateFromMessage(const cyberplanner::arm_state_t& message,
                                              const planner::RobotModel& robot, double margin = 0.5);

cyberplanner::arm_plan_status_t statusMessage(const StatusUpdate& update, std::int64_t utime);

// The most samples an ARM_TRAJECTORY of `num_joints` joints may carry: MAX_SAMPLES (1000), fewer
// than that when more joints would take the message past 60 kB (576 for 4 joints).
int maxTrajectorySamples(int num_joints);

// Samples at step_s, widened to duration / (maxTrajectorySamples - 2) for long trajectories so the
// samples cover the whole trajectory, the last one at its end (docs/lcm.md). `num_joints` is the
// robot's joint count.
cyberplanner::arm_trajectory_t trajectoryMessage(std::int64_t request_id, const SetpointSource& trajectory,
                                                 int num_joints, std::int64_t start_utime, double step_s,
                                                 std::int64_t utime);

// The snapshot's setpoints of the robot's `num_joints` joints.
cyberplanner::arm_setpoint_t setpointMessage(const StreamSnapshot& snapshot, int num_joints, std::int64_t utime);

}  // namespace cyber::daemon::io

#include "cyber/daemon/io/lcm_messages.hpp"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cyber::daemon::io {

namespace {

// ARM_TRAJECTORY stays below 60 kB encoded (docs/lcm.md, its "Size cap"):
// the fingerprint and the fields before the arrays take 53 bytes; a sample is t_s and three rows
// (position, velocity, volts) per joint, 8 bytes each.
constexpr int kTrajectoryBudgetBytes = 60'000;
constexpr int kTrajectoryHeaderBytes = 8 + 5 * 8 + 1 + 4;
constexpr int kTrajectoryRowsPerJoint = 3;
constexpr int kDoubleBytes = 8;

}  // namespace

std::int64_t wallMicros() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000 + ts.tv_nsec / 1000;
}

GoalRequest goalFromMessage(const cyberplanner::arm_goal_t& message) {
  GoalRequest goal;
  goal.request_id = message.request_id;
  goal.pose_name = message.pose_name;
  goal.position = message.position;  // as many as num_joints: validateGoal checks the count
  goal.num_pieces = message.num_pieces;
  goal.pieces = message.pieces;
  goal.scene_name = message.scene_name;
  goal.scene_offset_m = message.scene_offset_m;
  return goal;
}

std::optional<CancelRequest> cancelFromMessage(const cyberplanner::arm_cancel_t& message) {
  CancelRequest cancel;
  cancel.request_id = message.request_id;
  switch (message.action) {
    case cyberplanner::arm_cancel_t::ACTION_HOLD: cancel.action = CancelAction::kHold; break;
    case cyberplanner::arm_cancel_t::ACTION_RELEASE: cancel.action = CancelAction::kRelease; break;
    default: return std::nullopt;
  }
  return cancel;
}

std::optional<MeasuredState> stateFromMessage(const cyberplanner::arm_state_t& message,
                                              const planner::RobotModel& robot, double margin) {
  const size_t joints = robot.joints.size();
  if (message.num_joints < 0 || static_cast<size_t>(message.num_joints) != joints) return std::nullopt;
  if (message.position.size() != joints || message.velocity.size() != joints) return std::nullopt;
  MeasuredState state{planner::JointVector(static_cast<Eigen::Index>(joints)),
                      planner::JointVector(static_cast<Eigen::Index>(joints))};
  for (size_t j = 0; j < joints; ++j) {
    state.q[static_cast<Eigen::Index>(j)] = message.position[j];
    state.qdot[static_cast<Eigen::Index>(j)] = message.velocity[j];
  }
  if (!state.q.allFinite() || !state.qdot.allFinite()) return std::nullopt;
  if (!robot.withinLimits(state.q, margin)) return std::nullopt;
  return state;
}

cyberplanner::arm_plan_status_t statusMessage(const StatusUpdate& update, std::int64_t utime) {
  cyberplanner::arm_plan_status_t message{};
  message.utime = utime;
  message.request_id = update.request_id;
  message.status = static_cast<std::int8_t>(update.status);
  // LCM encodes a string only up to its first NUL but sizes the message by the whole string: cut
  // there, so the message is exactly what is sent (goal_request.cpp keeps NULs out of reasons).
  message.reason = update.reason.substr(0, update.reason.find('\0'));
  message.grid_ms = update.times_ms.grid;
  message.search_ms = update.times_ms.search;
  message.smooth_ms = update.times_ms.smooth;
  message.topp_ms = update.times_ms.topp;
  message.total_ms = update.times_ms.total;
  message.duration_s = update.duration_s;
  return message;
}

int maxTrajectorySamples(int num_joints) {
  const int per_sample = kDoubleBytes * (1 + kTrajectoryRowsPerJoint * std::max(0, num_joints));
  return std::min<int>(cyberplanner::arm_trajectory_t::MAX_SAMPLES,
                       (kTrajectoryBudgetBytes - kTrajectoryHeaderBytes) / per_sample);
}

cyberplanner::arm_trajectory_t trajectoryMessage(std::int64_t request_id, const SetpointSource& trajectory,
                                                 int num_joints, std::int64_t start_utime, double step_s,
                                                 std::int64_t utime) {
  const int kMax = maxTrajectorySamples(num_joints);
  cyberplanner::arm_trajectory_t message{};
  message.utime = utime;
  message.request_id = request_id;
  message.start_utime = start_utime;
  const double duration = std::max(0.0, trajectory.durationS());
  message.duration_s = duration;
  // Samples at k * dt, and one more at the end when the duration is not a multiple of dt: the
  // rest state the motion ends in is part of the plan. dt is widened so that both fit in kMax.
  const double dt = std::max(step_s, duration / (kMax - 2));
  message.dt_s = dt;
  const int on_step = static_cast<int>(std::floor(duration / dt + 1e-9)) + 1;
  const bool end_off_step = (on_step - 1) * dt < duration - 1e-6;  // else the last step sample moves to the end
  const int count = std::min(kMax, on_step + (end_off_step ? 1 : 0));
  message.num_samples = count;
  message.num_joints = static_cast<std::int8_t>(num_joints);
  // position, velocity and volts are [joint][sample]: num_joints rows of `count` each.
  message.t_s.resize(static_cast<size_t>(count));
  for (auto* table : {&message.position, &message.velocity, &message.volts}) {
    table->assign(static_cast<size_t>(num_joints), std::vector<double>(static_cast<size_t>(count)));
  }
  for (int k = 0; k < count; ++k) {
    const double t = k + 1 == count ? duration : std::min(duration, k * dt);
    const JointSetpoints s = trajectory.at(t);
    const auto i = static_cast<size_t>(k);
    message.t_s[i] = t;
    // Rows the setpoints do not have (a model of fewer joints than num_joints) stay 0.
    for (int j = 0; j < std::min(num_joints, static_cast<int>(s.position.size())); ++j) {
      const auto row = static_cast<size_t>(j);
      message.position[row][i] = s.position[j];
      message.velocity[row][i] = s.velocity[j];
      message.volts[row][i] = s.volts[j];
    }
  }
  return message;
}

cyberplanner::arm_setpoint_t setpointMessage(const StreamSnapshot& snapshot, int num_joints, std::int64_t utime) {
  cyberplanner::arm_setpoint_t message{};
  message.utime = utime;
  message.mode = static_cast<std::int8_t>(snapshot.mode);
  message.request_id = snapshot.request_id;
  message.trajectory_t_s = snapshot.mode == StreamMode::kMoving ? snapshot.segment_time_s : 0.0;
  message.num_joints = static_cast<std::int8_t>(num_joints);
  for (auto* row : {&message.position, &message.velocity, &message.volts})
    row->assign(static_cast<size_t>(num_joints), 0.0);
  message.sequence.assign(static_cast<size_t>(num_joints), 0);
  for (int j = 0; j < std::min(snapshot.joints.size(), num_joints); ++j) {
    const can::Setpoint& wire = snapshot.joints[j];
    message.position[j] = wire.position;
    message.velocity[j] = wire.velocity;
    message.volts[j] = wire.feedforward_volts;
    message.sequence[j] = wire.sequence;
  }
  return message;
}

}  // namespace cyber::daemon::io

#include <gtest/gtest.h>

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "cyber/can/status_codec.hpp"
#include "cyber/lcmtypes/constant_names.hpp"
#include "cyber/lcmtypes/safe_decode.hpp"
#include "cyberplanner/arm_daemon_status_t.hpp"
#include "cyberplanner/arm_goal_t.hpp"
#include "cyberplanner/arm_plan_status_t.hpp"
#include "cyberplanner/arm_setpoint_t.hpp"
#include "cyberplanner/arm_state_t.hpp"
#include "cyberplanner/arm_trajectory_t.hpp"

namespace {

using namespace cyberplanner;  // NOLINT: the generated types' package

template <class Message>
std::vector<std::uint8_t> encode(const Message& message) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  const int written = message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  EXPECT_EQ(written, static_cast<int>(bytes.size()));
  return bytes;
}

template <class Message>
Message decodeOk(const std::vector<std::uint8_t>& bytes) {
  Message out{};
  EXPECT_EQ(out.decode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
  return out;
}

class Values {
 public:
  explicit Values(unsigned seed) : rng_(seed) {}
  double real() { return std::uniform_real_distribution<double>(-1e3, 1e3)(rng_); }
  std::int64_t integer() { return std::uniform_int_distribution<std::int64_t>(INT64_MIN, INT64_MAX)(rng_); }
  std::int8_t small(int high) { return static_cast<std::int8_t>(std::uniform_int_distribution<int>(0, high)(rng_)); }
  bool flag() { return std::bernoulli_distribution(0.5)(rng_); }

 private:
  std::mt19937_64 rng_;
};

arm_goal_t randomGoal(Values& v) {
  arm_goal_t m{};
  m.utime = v.integer();
  m.request_id = v.integer();
  // Named goals and goals of 0 .. MAX_JOINTS values (a named one may send none).
  m.pose_name = v.flag() ? "" : "L3";
  m.num_joints = v.small(arm_goal_t::MAX_JOINTS);
  for (int j = 0; j < m.num_joints; ++j) m.position.push_back(v.real());
  m.num_pieces = v.small(arm_goal_t::MAX_PIECES);
  for (int i = 0; i < m.num_pieces; ++i) m.pieces.push_back(v.flag() ? "coral" : "piece-" + std::to_string(i));
  m.scene_name = v.flag() ? "" : "reef-left";
  m.scene_offset_m = v.real();
  return m;
}

TEST(LcmTypes, GoalRoundTrip) {
  Values v(1);
  for (int i = 0; i < 200; ++i) {
    const arm_goal_t in = randomGoal(v);
    const auto out = decodeOk<arm_goal_t>(encode(in));
    ASSERT_EQ(out.utime, in.utime);
    ASSERT_EQ(out.request_id, in.request_id);
    ASSERT_EQ(out.pose_name, in.pose_name);
    ASSERT_EQ(out.num_joints, in.num_joints);
    ASSERT_EQ(out.position, in.position);
    ASSERT_EQ(out.num_pieces, in.num_pieces);
    ASSERT_EQ(out.pieces, in.pieces);
    ASSERT_EQ(out.scene_offset_m, in.scene_offset_m);
    ASSERT_EQ(out.scene_name, in.scene_name);
  }
}

TEST(LcmTypes, StateRoundTrip) {
  Values v(2);
  for (int i = 0; i < 200; ++i) {
    arm_state_t in{};
    in.utime = v.integer();
    in.num_joints = static_cast<std::int8_t>(1 + v.small(arm_state_t::MAX_JOINTS - 1));
    for (int j = 0; j < in.num_joints; ++j) {
      in.position.push_back(v.real());
      in.velocity.push_back(v.real());
    }
    in.num_pieces = v.small(arm_state_t::MAX_PIECES);
    for (int k = 0; k < in.num_pieces; ++k) in.pieces.push_back("piece-" + std::to_string(k));
    const auto out = decodeOk<arm_state_t>(encode(in));
    ASSERT_EQ(out.utime, in.utime);
    ASSERT_EQ(out.num_joints, in.num_joints);
    ASSERT_EQ(out.position, in.position);
    ASSERT_EQ(out.velocity, in.velocity);
    ASSERT_EQ(out.pieces, in.pieces);
  }
}

TEST(LcmTypes, PlanStatusRoundTrip) {
  Values v(3);
  for (int i = 0; i < 200; ++i) {
    arm_plan_status_t in{};
    in.utime = v.integer();
    in.request_id = v.integer();
    in.status = v.small(arm_plan_status_t::STATUS_CANCELLED);
    in.reason = v.flag() ? "" : "goal in collision: arm vs. reef pipe, clearance 0.012 m < 0.03 m";
    in.grid_ms = v.real();
    in.search_ms = v.real();
    in.smooth_ms = v.real();
    in.topp_ms = v.real();
    in.total_ms = v.real();
    in.duration_s = v.real();
    const auto out = decodeOk<arm_plan_status_t>(encode(in));
    ASSERT_EQ(out.utime, in.utime);
    ASSERT_EQ(out.request_id, in.request_id);
    ASSERT_EQ(out.status, in.status);
    ASSERT_EQ(out.reason, in.reason);
    ASSERT_EQ(out.grid_ms, in.grid_ms);
    ASSERT_EQ(out.search_ms, in.search_ms);
    ASSERT_EQ(out.smooth_ms, in.smooth_ms);
    ASSERT_EQ(out.topp_ms, in.topp_ms);
    ASSERT_EQ(out.total_ms, in.total_ms);
    ASSERT_EQ(out.duration_s, in.duration_s);
  }
}

arm_trajectory_t randomTrajectory(Values& v, int samples, int joints = 2) {
  arm_trajectory_t m{};
  m.num_joints = static_cast<std::int8_t>(joints);
  m.utime = v.integer();
  m.request_id = v.integer();
  m.start_utime = v.integer();
  m.duration_s = v.real();
  m.dt_s = v.real();
  m.num_samples = samples;
  const auto n = static_cast<std::size_t>(samples);
  m.t_s.resize(n);
  for (double& x : m.t_s) x = v.real();
  // [joint][sample]: lcm-gen encodes num_joints rows of num_samples each.
  for (auto* table : {&m.position, &m.velocity, &m.volts}) {
    table->assign(static_cast<std::size_t>(joints), std::vector<double>(n));
    for (auto& row : *table) {
      for (double& x : row) x = v.real();
    }
  }
  return m;
}

TEST(LcmTypes, TrajectoryRoundTrip) {
  Values v(4);
  for (int samples : {0, 1, 2, 17, 999, static_cast<int>(arm_trajectory_t::MAX_SAMPLES)}) {
    const arm_trajectory_t in = randomTrajectory(v, samples, 1 + samples % arm_trajectory_t::MAX_JOINTS);
    const auto out = decodeOk<arm_trajectory_t>(encode(in));
    ASSERT_EQ(out.utime, in.utime);
    ASSERT_EQ(out.request_id, in.request_id);
    ASSERT_EQ(out.start_utime, in.start_utime);
    ASSERT_EQ(out.duration_s, in.duration_s);
    ASSERT_EQ(out.dt_s, in.dt_s);
    ASSERT_EQ(out.num_samples, in.num_samples);
    ASSERT_EQ(out.num_joints, in.num_joints);
    ASSERT_EQ(out.t_s, in.t_s);
    ASSERT_EQ(out.position, in.position);
    ASSERT_EQ(out.velocity, in.velocity);
    ASSERT_EQ(out.volts, in.volts);
  }
}

TEST(LcmTypes, FullTrajectoryStaysUnder60kB) {
  Values v(5);
  const arm_trajectory_t full = randomTrajectory(v, arm_trajectory_t::MAX_SAMPLES);
  EXPECT_EQ(full.getEncodedSize(), 56053);  // docs/lcm.md quotes this number
  EXPECT_LT(full.getEncodedSize(), 60000);
  EXPECT_EQ(static_cast<int>(encode(full).size()), full.getEncodedSize());
}

TEST(LcmTypes, SetpointRoundTrip) {
  Values v(6);
  for (int i = 0; i < 200; ++i) {
    arm_setpoint_t in{};
    in.utime = v.integer();
    in.mode = v.small(arm_setpoint_t::MODE_ROBOT_DISABLED);
    in.request_id = v.integer();
    in.trajectory_t_s = v.real();
    in.num_joints = static_cast<std::int8_t>(1 + v.small(arm_setpoint_t::MAX_JOINTS - 1));
    for (int j = 0; j < in.num_joints; ++j) {
      in.position.push_back(v.real());
      in.velocity.push_back(v.real());
      in.volts.push_back(v.real());
      in.sequence.push_back(static_cast<std::uint8_t>(v.integer()));
    }
    const auto out = decodeOk<arm_setpoint_t>(encode(in));
    ASSERT_EQ(out.utime, in.utime);
    ASSERT_EQ(out.mode, in.mode);
    ASSERT_EQ(out.request_id, in.request_id);
    ASSERT_EQ(out.trajectory_t_s, in.trajectory_t_s);
    ASSERT_EQ(out.num_joints, in.num_joints);
    ASSERT_EQ(out.position, in.position);
    ASSERT_EQ(out.velocity, in.velocity);
    ASSERT_EQ(out.volts, in.volts);
    ASSERT_EQ(out.sequence, in.sequence);
  }
}

TEST(LcmTypes, DaemonStatusRoundTrip) {
  Values v(7);
  for (int i = 0; i < 200; ++i) {
    arm_daemon_status_t in{};
    in.utime = v.integer();
    in.mode = v.small(arm_daemon_status_t::MODE_ROBOT_DISABLED);
    in.num_joints = 2;
    in.joint_names = {v.flag() ? "elevator" : "shoulder", "arm"};
    in.joint_units = {v.flag() ? "m" : "rad", "rad"};
    in.robot_enabled = v.flag();
    in.motion_allowed = v.flag();
    in.active_request_id = v.integer();
    in.state_age_ms = v.real();
    in.heartbeat_age_ms = v.real();
    in.goals_received = v.integer();
    in.plans_succeeded = v.integer();
    in.plans_failed = v.integer();
    in.frames_sent = v.integer();
    in.can_errors = v.integer();
    in.decode_errors = v.integer();
    in.stream_overruns = v.integer();
    in.publish_failures = v.integer();
    in.plan_time_p50_ms = v.real();
    in.plan_time_p99_ms = v.real();
    in.plan_time_max_ms = v.real();
    in.stream_jitter_p50_us = v.real();
    in.stream_jitter_p99_us = v.real();
    in.stream_jitter_max_us = v.real();
    const auto out = decodeOk<arm_daemon_status_t>(encode(in));
    ASSERT_EQ(out.utime, in.utime);
    ASSERT_EQ(out.mode, in.mode);
    ASSERT_EQ(out.num_joints, in.num_joints);
    ASSERT_EQ(out.joint_names, in.joint_names);
    ASSERT_EQ(out.joint_units, in.joint_units);
    ASSERT_EQ(out.robot_enabled, in.robot_enabled);
    ASSERT_EQ(out.motion_allowed, in.motion_allowed);
    ASSERT_EQ(out.active_request_id, in.active_request_id);
    ASSERT_EQ(out.state_age_ms, in.state_age_ms);
    ASSERT_EQ(out.heartbeat_age_ms, in.heartbeat_age_ms);
    ASSERT_EQ(out.goals_received, in.goals_received);
    ASSERT_EQ(out.plans_succeeded, in.plans_succeeded);
    ASSERT_EQ(out.plans_failed, in.plans_failed);
    ASSERT_EQ(out.frames_sent, in.frames_sent);
    ASSERT_EQ(out.can_errors, in.can_errors);
    ASSERT_EQ(out.decode_errors, in.decode_errors);
    ASSERT_EQ(out.stream_overruns, in.stream_overruns);
    ASSERT_EQ(out.publish_failures, in.publish_failures);
    ASSERT_EQ(out.plan_time_p50_ms, in.plan_time_p50_ms);
    ASSERT_EQ(out.plan_time_p99_ms, in.plan_time_p99_ms);
    ASSERT_EQ(out.plan_time_max_ms, in.plan_time_max_ms);
    ASSERT_EQ(out.stream_jitter_p50_us, in.stream_jitter_p50_us);
    ASSERT_EQ(out.stream_jitter_p99_us, in.stream_jitter_p99_us);
    ASSERT_EQ(out.stream_jitter_max_us, in.stream_jitter_max_us);
  }
}

TEST(LcmTypes, ModeConstantsMatchTheCanStatusModes) {
  using cyber::can::Mode;
  EXPECT_EQ(arm_setpoint_t::MODE_NO_STATE, static_cast<int>(Mode::kNoState));
  EXPECT_EQ(arm_setpoint_t::MODE_HOLDING, static_cast<int>(Mode::kHolding));
  EXPECT_EQ(arm_setpoint_t::MODE_MOVING, static_cast<int>(Mode::kMoving));
  EXPECT_EQ(arm_setpoint_t::MODE_FAULT, static_cast<int>(Mode::kFault));
  EXPECT_EQ(arm_setpoint_t::MODE_ROBOT_DISABLED, static_cast<int>(Mode::kRobotDisabled));
  EXPECT_EQ(arm_setpoint_t::MODE_RELEASED, static_cast<int>(Mode::kReleased));
  EXPECT_EQ(arm_daemon_status_t::MODE_NO_STATE, static_cast<int>(Mode::kNoState));
  EXPECT_EQ(arm_daemon_status_t::MODE_HOLDING, static_cast<int>(Mode::kHolding));
  EXPECT_EQ(arm_daemon_status_t::MODE_MOVING, static_cast<int>(Mode::kMoving));
  EXPECT_EQ(arm_daemon_status_t::MODE_FAULT, static_cast<int>(Mode::kFault));
  EXPECT_EQ(arm_daemon_status_t::MODE_ROBOT_DISABLED, static_cast<int>(Mode::kRobotDisabled));
  EXPECT_EQ(arm_daemon_status_t::MODE_RELEASED, static_cast<int>(Mode::kReleased));
  EXPECT_STREQ(cyber::lcmtypes::modeName(arm_daemon_status_t::MODE_RELEASED), "RELEASED");
}

TEST(LcmTypes, FingerprintMismatchFails) {
  Values v(8);
  const auto goal_bytes = encode(randomGoal(v));
  arm_state_t state{};
  EXPECT_LT(state.decode(goal_bytes.data(), 0, static_cast<int>(goal_bytes.size())), 0);
  arm_plan_status_t status{};
  EXPECT_LT(status.decode(goal_bytes.data(), 0, static_cast<int>(goal_bytes.size())), 0);
  EXPECT_LT(cyber::lcmtypes::safeDecode(state, goal_bytes.data(), static_cast<int>(goal_bytes.size())), 0);
  // Every type has its own fingerprint.
  const std::int64_t hashes[] = {arm_goal_t::getHash(),        arm_state_t::getHash(),
                                 arm_plan_status_t::getHash(), arm_trajectory_t::getHash(),
                                 arm_setpoint_t::getHash(),    arm_daemon_status_t::getHash()};
  for (std::size_t i = 0; i < std::size(hashes); ++i) {
    for (std::size_t j = i + 1; j < std::size(hashes); ++j) EXPECT_NE(hashes[i], hashes[j]);
  }
}

TEST(LcmTypes, TruncatedMessagesFail) {
  Values v(9);
  const auto bytes = encode(randomGoal(v));
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    arm_goal_t goal{};
    ASSERT_LT(cyber::lcmtypes::safeDecode(goal, bytes.data(), static_cast<int>(length)), 0) << length;
  }
  const auto trajectory_bytes = encode(randomTrajectory(v, 10));
  for (std::size_t length = 0; length < trajectory_bytes.size(); ++length) {
    arm_trajectory_t trajectory{};
    ASSERT_LT(cyber::lcmtypes::safeDecode(trajectory, trajectory_bytes.data(), static_cast<int>(length)), 0);
  }
}

TEST(LcmTypes, GarbageBytesFailCleanly) {
  std::mt19937 rng(10);
  std::uniform_int_distribution<int> byte(0, 255), length(0, 300);
  for (int i = 0; i < 2000; ++i) {
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(length(rng)));
    for (auto& b : bytes) b = static_cast<std::uint8_t>(byte(rng));
    arm_goal_t goal{};
    arm_trajectory_t trajectory{};
    arm_daemon_status_t status{};
    ASSERT_LT(cyber::lcmtypes::safeDecode(goal, bytes.data(), static_cast<int>(bytes.size())), 0);
    ASSERT_LT(cyber::lcmtypes::safeDecode(trajectory, bytes.data(), static_cast<int>(bytes.size())), 0);
    ASSERT_LT(cyber::lcmtypes::safeDecode(status, bytes.data(), static_cast<int>(bytes.size())), 0);
  }
}

// Write a big-endian int32 at offset (LCM's wire order).
void putInt32(std::vector<std::uint8_t>& bytes, std::size_t offset, std::int32_t value) {
  const auto bits = static_cast<std::uint32_t>(value);
  for (int i = 0; i < 4; ++i)
    bytes[offset + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(bits >> (24 - 8 * i));
}

std::int32_t getInt32(const std::vector<std::uint8_t>& bytes, std::size_t offset) {
  std::uint32_t bits = 0;
  for (int i = 0; i < 4; ++i) bits = (bits << 8) | bytes[offset + static_cast<std::size_t>(i)];
  return static_cast<std::int32_t>(bits);
}

// Where the length and count fields sit in message version 3 (after the 8-byte fingerprint), for
// 2 joints and an empty pose_name: safeDecode walks to them; these tests corrupt them there.
constexpr std::size_t kGoalPoseNameLengthAt = 8 + 2 * 8;                    // utime, request_id
constexpr std::size_t kGoalJointCountAt = kGoalPoseNameLengthAt + 4 + 1;    // pose_name "" (length 1)
constexpr std::size_t kGoalPieceCountAt = kGoalJointCountAt + 1 + 2 * 8;    // position[2]
constexpr std::size_t kGoalSceneNameLengthAt = kGoalPieceCountAt + 1;       // with no pieces
constexpr std::size_t kStateJointCountAt = 8 + 8;                           // utime
constexpr std::size_t kStatePieceCountAt = kStateJointCountAt + 1 + 4 * 8;  // position[2], velocity[2]
constexpr std::size_t kSetpointJointCountAt = 8 + 8 + 1 + 2 * 8;            // utime, mode, request_id, trajectory_t_s
constexpr std::size_t kPlanStatusReasonLengthAt = 8 + 2 * 8 + 1;
constexpr std::size_t kDaemonStatusJointCountAt = 8 + 8 + 1;                      // utime, mode
constexpr std::size_t kDaemonStatusNameLengthAt = kDaemonStatusJointCountAt + 1;  // joint_names[0]
constexpr std::size_t kTrajectoryJointCountAt = 8 + 5 * 8;
constexpr std::size_t kTrajectoryCountAt = kTrajectoryJointCountAt + 1;

// The messages the layout and corruption tests start from: 2 joints, no pose name.
arm_goal_t twoJointGoal(Values& v) {
  arm_goal_t goal = randomGoal(v);
  goal.pose_name = "";
  goal.num_joints = 2;
  goal.position = {v.real(), v.real()};
  goal.num_pieces = 0;
  goal.pieces.clear();
  return goal;
}
arm_state_t twoJointState() {
  arm_state_t state{};
  state.num_joints = 2;
  state.position = {0.5, 1.0};
  state.velocity = {0.0, 0.0};
  state.num_pieces = 1;
  state.pieces = {"coral"};
  return state;
}
arm_daemon_status_t twoJointStatus() {
  arm_daemon_status_t daemon{};
  daemon.num_joints = 2;
  daemon.joint_names = {"elevator", "arm"};
  daemon.joint_units = {"m", "rad"};
  return daemon;
}

TEST(LcmTypes, TheLengthFieldsAreWhereTheTestsCorruptThem) {
  Values v(13);
  arm_goal_t goal = twoJointGoal(v);
  goal.scene_name = "reef-left";
  EXPECT_EQ(getInt32(encode(goal), kGoalPoseNameLengthAt), 1);
  EXPECT_EQ(encode(goal)[kGoalJointCountAt], 2);
  EXPECT_EQ(encode(goal)[kGoalPieceCountAt], 0);
  EXPECT_EQ(getInt32(encode(goal), kGoalSceneNameLengthAt), 10);  // with the NUL
  const arm_state_t state = twoJointState();
  EXPECT_EQ(encode(state)[kStateJointCountAt], 2);
  EXPECT_EQ(encode(state)[kStatePieceCountAt], 1);
  EXPECT_EQ(getInt32(encode(state), kStatePieceCountAt + 1), 6);
  arm_plan_status_t status{};
  status.reason = "no path";
  EXPECT_EQ(getInt32(encode(status), kPlanStatusReasonLengthAt), 8);
  EXPECT_EQ(encode(twoJointStatus())[kDaemonStatusJointCountAt], 2);
  EXPECT_EQ(getInt32(encode(twoJointStatus()), kDaemonStatusNameLengthAt), 9);
  arm_setpoint_t setpoint{};
  setpoint.num_joints = 3;
  setpoint.position = setpoint.velocity = setpoint.volts = {0, 0, 0};
  setpoint.sequence = {0, 0, 0};
  EXPECT_EQ(encode(setpoint)[kSetpointJointCountAt], 3);
  EXPECT_EQ(encode(randomTrajectory(v, 37, 3))[kTrajectoryJointCountAt], 3);
  EXPECT_EQ(getInt32(encode(randomTrajectory(v, 37)), kTrajectoryCountAt), 37);
}

TEST(LcmTypes, CorruptLengthFieldsAfterAValidFingerprintFailCleanly) {
  Values v(11);
  arm_goal_t goal = twoJointGoal(v);
  goal.scene_name = "reef";
  auto goal_bytes = encode(goal);
  for (std::int32_t bad : {0, -1, -100, INT32_MIN, 14, 1000, INT32_MAX}) {
    putInt32(goal_bytes, kGoalSceneNameLengthAt, bad);
    arm_goal_t out{};
    EXPECT_LT(cyber::lcmtypes::safeDecode(out, goal_bytes.data(), static_cast<int>(goal_bytes.size())), 0) << bad;
  }
  // A piece or joint count the bytes do not hold, or a negative one (lcm-gen would size the array
  // by it).
  for (const std::size_t at : {kGoalPieceCountAt, kGoalJointCountAt}) {
    for (std::uint8_t bad : {std::uint8_t{0xff}, std::uint8_t{0x80}, std::uint8_t{4}, std::uint8_t{127}}) {
      auto bytes = encode(goal);
      bytes[at] = bad;
      arm_goal_t out{};
      EXPECT_LT(cyber::lcmtypes::safeDecode(out, bytes.data(), static_cast<int>(bytes.size())), 0) << int{bad};
    }
  }
  for (std::int32_t bad : {0, -1, INT32_MIN, 100, INT32_MAX}) {
    auto bytes = encode(goal);
    putInt32(bytes, kGoalPoseNameLengthAt, bad);
    arm_goal_t out{};
    EXPECT_LT(cyber::lcmtypes::safeDecode(out, bytes.data(), static_cast<int>(bytes.size())), 0) << bad;
  }
  const arm_state_t state = twoJointState();
  for (std::uint8_t bad : {std::uint8_t{0xff}, std::uint8_t{0x80}, std::uint8_t{5}, std::uint8_t{127}}) {
    auto bytes = encode(state);
    bytes[kStateJointCountAt] = bad;
    arm_state_t out{};
    EXPECT_LT(cyber::lcmtypes::safeDecode(out, bytes.data(), static_cast<int>(bytes.size())), 0) << int{bad};
  }
  arm_setpoint_t setpoint{};
  setpoint.num_joints = 2;
  setpoint.position = setpoint.velocity = setpoint.volts = {0, 0};
  setpoint.sequence = {0, 0};
  for (std::uint8_t bad : {std::uint8_t{0xff}, std::uint8_t{0x80}, std::uint8_t{3}, std::uint8_t{127}}) {
    auto bytes = encode(setpoint);
    bytes[kSetpointJointCountAt] = bad;
    arm_setpoint_t out{};
    EXPECT_LT(cyber::lcmtypes::safeDecode(out, bytes.data(), static_cast<int>(bytes.size())), 0) << int{bad};
  }
  for (std::int32_t bad : {0, -1, INT32_MIN, 7, INT32_MAX}) {
    auto bytes = encode(state);
    putInt32(bytes, kStatePieceCountAt + 1, bad);
    arm_state_t out{};
    EXPECT_LT(cyber::lcmtypes::safeDecode(out, bytes.data(), static_cast<int>(bytes.size())), 0) << bad;
  }
  {
    auto bytes = encode(state);
    bytes[kStatePieceCountAt] = 0xff;
    arm_state_t out{};
    EXPECT_LT(cyber::lcmtypes::safeDecode(out, bytes.data(), static_cast<int>(bytes.size())), 0);
  }

  arm_plan_status_t status{};
  status.reason = "x";
  auto status_bytes = encode(status);
  for (std::int32_t bad : {0, INT32_MIN, 3, INT32_MAX}) {
    putInt32(status_bytes, kPlanStatusReasonLengthAt, bad);
    arm_plan_status_t out{};
    EXPECT_LT(cyber::lcmtypes::safeDecode(out, status_bytes.data(), static_cast<int>(status_bytes.size())), 0) << bad;
  }

  auto daemon_bytes = encode(twoJointStatus());
  for (std::uint8_t bad : {std::uint8_t{0xff}, std::uint8_t{3}, std::uint8_t{127}}) {
    auto bytes = daemon_bytes;
    bytes[kDaemonStatusJointCountAt] = bad;
    arm_daemon_status_t out{};
    EXPECT_LT(cyber::lcmtypes::safeDecode(out, bytes.data(), static_cast<int>(bytes.size())), 0) << int{bad};
  }
  for (std::int32_t bad : {0, -1, INT32_MIN, INT32_MAX}) {
    putInt32(daemon_bytes, kDaemonStatusNameLengthAt, bad);
    arm_daemon_status_t out{};
    EXPECT_LT(cyber::lcmtypes::safeDecode(out, daemon_bytes.data(), static_cast<int>(daemon_bytes.size())), 0) << bad;
  }

  auto trajectory_bytes = encode(randomTrajectory(v, 3));
  for (std::int32_t bad : {-1, INT32_MIN, 4, static_cast<int>(arm_trajectory_t::MAX_SAMPLES) + 1, INT32_MAX}) {
    putInt32(trajectory_bytes, kTrajectoryCountAt, bad);
    arm_trajectory_t out{};
    EXPECT_LT(cyber::lcmtypes::safeDecode(out, trajectory_bytes.data(), static_cast<int>(trajectory_bytes.size())), 0)
        << bad;
  }
  for (std::uint8_t bad : {std::uint8_t{0xff}, std::uint8_t{0x80}, std::uint8_t{3}, std::uint8_t{127}}) {
    auto bytes = encode(randomTrajectory(v, 3));
    bytes[kTrajectoryJointCountAt] = bad;
    arm_trajectory_t out{};
    EXPECT_LT(cyber::lcmtypes::safeDecode(out, bytes.data(), static_cast<int>(bytes.size())), 0) << int{bad};
  }
}

TEST(LcmTypes, SafeDecodeAcceptsEveryValidMessage) {
  Values v(14);
  for (int i = 0; i < 50; ++i) {
    const auto goal_bytes = encode(randomGoal(v));
    arm_goal_t goal{};
    ASSERT_EQ(cyber::lcmtypes::safeDecode(goal, goal_bytes.data(), static_cast<int>(goal_bytes.size())),
              static_cast<int>(goal_bytes.size()));
  }
  arm_state_t held = twoJointState();
  held.num_pieces = 4;
  held.pieces = {"a", "b", "c", "d"};
  const auto state_bytes = encode(held);
  arm_state_t state{};
  EXPECT_EQ(cyber::lcmtypes::safeDecode(state, state_bytes.data(), static_cast<int>(state_bytes.size())),
            static_cast<int>(state_bytes.size()));
  const arm_daemon_status_t named = twoJointStatus();
  const auto named_bytes = encode(named);
  arm_daemon_status_t daemon{};
  EXPECT_EQ(cyber::lcmtypes::safeDecode(daemon, named_bytes.data(), static_cast<int>(named_bytes.size())),
            static_cast<int>(named_bytes.size()));
  arm_plan_status_t empty_reason{};
  const auto status_bytes = encode(empty_reason);
  arm_plan_status_t status{};
  EXPECT_EQ(cyber::lcmtypes::safeDecode(status, status_bytes.data(), static_cast<int>(status_bytes.size())),
            static_cast<int>(status_bytes.size()));
  const auto full_bytes = encode(randomTrajectory(v, arm_trajectory_t::MAX_SAMPLES));
  arm_trajectory_t full{};
  EXPECT_EQ(cyber::lcmtypes::safeDecode(full, full_bytes.data(), static_cast<int>(full_bytes.size())),
            static_cast<int>(full_bytes.size()));
  EXPECT_EQ(full.num_samples, arm_trajectory_t::MAX_SAMPLES);
  for (int joints = 0; joints <= arm_trajectory_t::MAX_JOINTS; ++joints) {
    const auto bytes = encode(randomTrajectory(v, 5, joints));
    arm_trajectory_t out{};
    EXPECT_EQ(cyber::lcmtypes::safeDecode(out, bytes.data(), static_cast<int>(bytes.size())),
              static_cast<int>(bytes.size()))
        << joints;
  }
  for (int joints = 0; joints <= arm_setpoint_t::MAX_JOINTS; ++joints) {
    arm_setpoint_t setpoint{};
    setpoint.num_joints = static_cast<std::int8_t>(joints);
    setpoint.position = setpoint.velocity = setpoint.volts = std::vector<double>(static_cast<std::size_t>(joints));
    setpoint.sequence = std::vector<std::uint8_t>(static_cast<std::size_t>(joints));
    const auto bytes = encode(setpoint);
    arm_setpoint_t out{};
    EXPECT_EQ(cyber::lcmtypes::safeDecode(out, bytes.data(), static_cast<int>(bytes.size())),
              static_cast<int>(bytes.size()))
        << joints;
  }
}

class GoalCatcher {
 public:
  void onGoal(const lcm::ReceiveBuffer* /*buffer*/, const std::string& channel, const arm_goal_t* goal) {
    channels.push_back(channel);
    goals.push_back(*goal);
  }
  std::vector<std::string> channels;
  std::vector<arm_goal_t> goals;
};

TEST(LcmTypes, MemqPublishSubscribe) {
  lcm::LCM lcm("memq://");
  ASSERT_TRUE(lcm.good());
  GoalCatcher catcher;
  ASSERT_NE(lcm.subscribe("ARM_GOAL", &GoalCatcher::onGoal, &catcher), nullptr);

  Values v(12);
  const arm_goal_t sent = randomGoal(v);
  ASSERT_EQ(lcm.publish("ARM_GOAL", &sent), 0);
  arm_state_t other{};
  ASSERT_EQ(lcm.publish("ARM_STATE", &other), 0);  // no subscriber: not delivered to us
  EXPECT_GT(lcm.handleTimeout(1000), 0);
  EXPECT_EQ(lcm.handleTimeout(0), 0);  // only the subscribed message was queued for us

  ASSERT_EQ(catcher.goals.size(), 1u);
  EXPECT_EQ(catcher.channels[0], "ARM_GOAL");
  EXPECT_EQ(catcher.goals[0].request_id, sent.request_id);
  EXPECT_EQ(catcher.goals[0].position, sent.position);
  EXPECT_EQ(catcher.goals[0].pose_name, sent.pose_name);
  EXPECT_EQ(catcher.goals[0].pieces, sent.pieces);
  EXPECT_EQ(catcher.goals[0].scene_name, sent.scene_name);
}

}  // namespace

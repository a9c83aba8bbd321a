// An LCM log holding every cyberplanner message (seeded random values, as lcm-logger records
// them) converted to WPILOG and read back: every entry is there, with the message's values at
// the event's time on the log's clock. The entry names are the ones docs/operations.md lists.
// With CYBER_LCM_LOG=FILE the same checks run on a recorded session instead (tools/demo's
// lcm.log: docs/operations.md, "AdvantageScope"). Chains of one, two and three joints (the
// shipped robots and one built here) each get their joints' entries and a pose per link.
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <random>
#include <set>

#include "cyber/config/load_config.hpp"
#include "cyber/planner.hpp"
#include "cyber/wpilog/lcm_to_wpilog.hpp"
#include "cyber/wpilog/pose3d.hpp"
#include "cyber/wpilog/wpilog_reader.hpp"
#include "cyberplanner/arm_daemon_status_t.hpp"
#include "cyberplanner/arm_goal_t.hpp"
#include "cyberplanner/arm_plan_status_t.hpp"
#include "cyberplanner/arm_setpoint_t.hpp"
#include "cyberplanner/arm_state_t.hpp"
#include "cyberplanner/arm_trajectory_t.hpp"

namespace cyber::wpilog {
namespace {

// cyber-wpilog's held pieces: the names joined by ',' or "none".
std::string pieceList(const std::vector<std::string>& pieces) {
  std::string out;
  for (const auto& piece : pieces) out += (out.empty() ? "" : ",") + piece;
  return out.empty() ? "none" : out;
}

constexpr int64_t kSyntheticT0 = 1'700'000'000'000'000;  // Unix µs of the earliest event
// lcm-logger wrote a recording's ARM_GOAL before an ARM_STATE it had received 36 µs earlier; the
// synthetic log's first event is as late after its second.
constexpr int64_t kFirstEventLateUs = 36;

// A random trajectory of `joints` joints for request `k`, published at `utime` and starting 5 ms
// later: `min_samples` to `min_samples` + 19 samples 10 ms apart, the positions drawn by
// position(joint), the velocities and volts from -3 to 3. Each sample draws its values array by
// array: the joints' positions, then their velocities, then their volts.
cyberplanner::arm_trajectory_t randomTrajectory(std::mt19937_64& rng, size_t joints, int64_t utime, int k,
                                                int min_samples, const std::function<double(size_t)>& position) {
  std::uniform_real_distribution<double> u(-3, 3);
  cyberplanner::arm_trajectory_t m{};
  m.utime = utime;
  m.request_id = k;
  m.start_utime = utime + 5000;
  m.dt_s = 0.01;
  m.num_samples = min_samples + static_cast<int>(rng() % 20);
  m.num_joints = static_cast<int8_t>(joints);
  for (auto* table : {&m.position, &m.velocity, &m.volts}) table->resize(joints);
  for (int i = 0; i < m.num_samples; ++i) {
    m.t_s.push_back(i * m.dt_s);
    for (size_t j = 0; j < joints; ++j) m.position[j].push_back(position(j));
    for (auto* table : {&m.velocity, &m.volts}) {
      for (auto& row : *table) row.push_back(u(rng));
    }
  }
  m.duration_s = m.t_s.back();
  return m;
}

struct Session {
  int64_t t0 = 0;  // Unix µs of the log's earliest event, wherever it is in the file
  std::vector<std::pair<int64_t, cyberplanner::arm_state_t>> states;
  std::vector<std::pair<int64_t, cyberplanner::arm_setpoint_t>> setpoints;
  std::vector<std::pair<int64_t, cyberplanner::arm_goal_t>> goals;
  std::vector<std::pair<int64_t, cyberplanner::arm_plan_status_t>> statuses;
  std::vector<std::pair<int64_t, cyberplanner::arm_trajectory_t>> trajectories;
  std::vector<std::pair<int64_t, cyberplanner::arm_daemon_status_t>> daemon;
};

// An LCM log converted with a robot's geometry, and what the tests need to read it: the messages
// as the log holds them (s_) and the WPILOG made of them (log_).
class ConvertedLog {
 protected:
  // Converts path_ for `config` and reads both back.
  void convert(const config::Config& config) {
    read();
    auto conversion = convertLcmLog(path_.string(), config.daemon.channels, mechanismGeometry(config.robot));
    ASSERT_TRUE(conversion.ok()) << conversion.error().message;
    writer_ = std::move(conversion.value().writer);
    stats_ = conversion->stats;
    auto r = parse(writer_.bytes());
    ASSERT_TRUE(r.ok()) << r.error().message;
    log_ = std::move(r).value();
  }

  // The messages as the log holds them, decoded by the generated code.
  void read() {
    lcm::LogFile log(path_.string(), "r");
    ASSERT_TRUE(log.good()) << path_;
    s_.t0 = std::numeric_limits<int64_t>::max();
    for (const lcm::LogEvent* e = log.readNextEvent(); e != nullptr; e = log.readNextEvent()) {
      s_.t0 = std::min(s_.t0, e->timestamp);
      take(*e, "ARM_STATE", s_.states);
      take(*e, "ARM_SETPOINT", s_.setpoints);
      take(*e, "ARM_GOAL", s_.goals);
      take(*e, "ARM_PLAN_STATUS", s_.statuses);
      take(*e, "ARM_TRAJECTORY", s_.trajectories);
      take(*e, "ARM_DAEMON_STATUS", s_.daemon);
    }
    // The entries are in time order whatever order the logger wrote the messages in.
    inTimeOrder(s_.states), inTimeOrder(s_.setpoints), inTimeOrder(s_.goals);
    inTimeOrder(s_.statuses), inTimeOrder(s_.trajectories), inTimeOrder(s_.daemon);
  }
  template <typename Message>
  static void inTimeOrder(std::vector<std::pair<int64_t, Message>>& messages) {
    std::stable_sort(messages.begin(), messages.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  }
  template <typename Message>
  static void take(const lcm::LogEvent& e, const char* channel, std::vector<std::pair<int64_t, Message>>& into) {
    Message m{};
    if (e.channel == channel && m.decode(e.data, 0, e.datalen) >= 0) into.emplace_back(e.timestamp, std::move(m));
  }

  template <typename Message>
  void event(lcm::LogFile& log, const std::string& channel, int64_t t, const Message& m) {
    std::vector<char> buffer(static_cast<size_t>(m.getEncodedSize()));
    m.encode(buffer.data(), 0, static_cast<int>(buffer.size()));
    raw(log, channel, t, buffer);
  }
  void raw(lcm::LogFile& log, const std::string& channel, int64_t t, std::vector<char>& bytes) {
    lcm::LogEvent e{};
    e.eventnum = events_++;
    e.timestamp = t;
    e.channel = channel;
    e.datalen = static_cast<int32_t>(bytes.size());
    e.data = bytes.data();
    ASSERT_EQ(log.writeEvent(&e), 0);
  }

  // The records of an entry, which must exist and have `type`.
  std::vector<const Record*> records(const std::string& name, const std::string& type) {
    const auto index = log_.find("/CyberPlanner/" + name);
    if (!index) {
      ADD_FAILURE() << "no entry /CyberPlanner/" << name;
      return {};
    }
    EXPECT_EQ(log_.entries[*index].type, type) << name;
    return log_.recordsOf(*index);
  }

  // Entry `name` has one record per message, at the message's time, with value(message).
  template <typename Message, typename Value>
  void expectSeries(const std::vector<std::pair<int64_t, Message>>& messages, const std::string& name,
                    const std::function<Value(const Message&)>& value) {
    const std::string type = std::is_same_v<Value, double>    ? "double"
                             : std::is_same_v<Value, int64_t> ? "int64"
                             : std::is_same_v<Value, bool>    ? "boolean"
                                                              : "string";
    const auto rs = records(name, type);
    ASSERT_EQ(rs.size(), messages.size()) << name;
    for (size_t i = 0; i < rs.size(); ++i) {
      EXPECT_EQ(rs[i]->timestamp_us, static_cast<uint64_t>(messages[i].first - s_.t0)) << name;
      const auto p = log_.payload(*rs[i]);
      if constexpr (std::is_same_v<Value, double>) {
        EXPECT_EQ(asDouble(p), value(messages[i].second)) << name;
      } else if constexpr (std::is_same_v<Value, int64_t>) {
        EXPECT_EQ(asInt64(p), value(messages[i].second)) << name;
      } else if constexpr (std::is_same_v<Value, bool>) {
        EXPECT_EQ(asBoolean(p), value(messages[i].second)) << name;
      } else {
        EXPECT_EQ(asString(p), value(messages[i].second)) << name;
      }
    }
  }

  using Table = std::vector<std::vector<double>> cyberplanner::arm_trajectory_t::*;

  // Planned series `name` holds row `joint` of `table` of every trajectory, sample k at
  // start_utime + t_s[k] on the log's clock ((start_utime - utime) after the message's own time),
  // until the next trajectory starts; returns how many samples a later trajectory replaced.
  size_t expectPlanned(const std::string& name, Table table, size_t joint) {
    const auto rs = records(name, "double");
    size_t r = 0, replaced = 0;
    auto startOf = [&](size_t i) {
      const auto& [t, m] = s_.trajectories[i];
      return t - s_.t0 + (m.start_utime - m.utime);
    };
    for (size_t i = 0; i < s_.trajectories.size(); ++i) {
      const auto& m = s_.trajectories[i].second;
      const int64_t next = i + 1 < s_.trajectories.size() ? startOf(i + 1) : std::numeric_limits<int64_t>::max();
      for (size_t k = 0; k < m.t_s.size(); ++k) {
        const int64_t at = startOf(i) + std::llround(m.t_s[k] * 1e6);
        replaced += at >= next ? 1 : 0;
        if (at < 0 || at >= next) continue;  // before the log's first event, or replaced
        if (r >= rs.size()) {
          ADD_FAILURE() << name << ": only " << rs.size() << " records";
          return replaced;
        }
        EXPECT_EQ(rs[r]->timestamp_us, static_cast<uint64_t>(at)) << name;
        EXPECT_EQ(asDouble(log_.payload(*rs[r])), (m.*table)[joint][k]) << name;
        ++r;
      }
    }
    EXPECT_EQ(r, rs.size()) << name;
    for (size_t k = 1; k < rs.size(); ++k) EXPECT_LT(rs[k - 1]->timestamp_us, rs[k]->timestamp_us) << name;
    return replaced;
  }

  // Every record of Mechanism3d/<which> holds one pose per link at the message's position: link
  // k's frame (planner::linkFrames) in the side view plane, x forward and the side view's y as z,
  // turned about +y so that the link's +x points along its side view angle.
  template <typename Message>
  void expectPoses(const std::string& which, const std::vector<std::pair<int64_t, Message>>& messages,
                   const planner::JointChain& chain) {
    const auto rs = records("Mechanism3d/" + which, "struct:Pose3d[]");
    ASSERT_EQ(rs.size(), messages.size()) << which;
    for (size_t i = 0; i < rs.size(); ++i) {
      EXPECT_EQ(rs[i]->timestamp_us, static_cast<uint64_t>(messages[i].first - s_.t0)) << which;
      const auto frames = planner::linkFrames(chain, jointVector(messages[i].second.position));
      std::vector<Pose3d> poses;
      ASSERT_TRUE(unpackPose3dArray(log_.payload(*rs[i]), &poses)) << which;
      ASSERT_EQ(poses.size(), static_cast<size_t>(chain.size())) << which;
      for (int k = 0; k < chain.size(); ++k) {
        const Pose3d& p = poses[static_cast<size_t>(k)];
        const planner::LinkFrame& f = frames[k];
        EXPECT_NEAR(p.x, f.origin_m.x(), 1e-12) << which << " link " << k;
        EXPECT_EQ(p.y, 0.0) << which << " link " << k;
        EXPECT_NEAR(p.z, f.origin_m.y(), 1e-12) << which << " link " << k;
        EXPECT_NEAR(p.qw * p.qw + p.qx * p.qx + p.qy * p.qy + p.qz * p.qz, 1.0, 1e-12) << which << " link " << k;
        // The link's +x axis rotated by the quaternion: (1 - 2(qy^2 + qz^2), 2(qx qy + qw qz),
        // 2(qx qz - qw qy)), which is (cos, 0, sin) of the link's angle.
        EXPECT_NEAR(1 - 2 * (p.qy * p.qy + p.qz * p.qz), f.cos_angle, 1e-12) << which << " link " << k;
        EXPECT_NEAR(2 * (p.qx * p.qy + p.qw * p.qz), 0.0, 1e-12) << which << " link " << k;
        EXPECT_NEAR(2 * (p.qx * p.qz - p.qw * p.qy), f.sin_angle, 1e-12) << which << " link " << k;
      }
    }
  }

  // Mechanism2d/<which> has a ligament per joint, each the child of the one before and named by
  // its joint. Walked from the root (the canvas's middle is the robot's origin), each ligament ends
  // where the next joint sits in its link, and the last one at the far end of its link's outline
  // along the link's x axis, at the message's position (planner::linkFrames).
  template <typename Message>
  void expectLigaments(const std::string& which, const std::vector<std::pair<int64_t, Message>>& messages,
                       const planner::RobotModel& robot) {
    const std::string m = "Mechanism2d/" + which + "/";
    const auto dims = records(m + "dims", "double[]");
    const auto base_x = records(m + "Base/x", "double");
    const auto base_y = records(m + "Base/y", "double");
    ASSERT_EQ(dims.size(), 1u) << which;
    ASSERT_EQ(base_x.size(), 1u) << which;
    ASSERT_EQ(base_y.size(), 1u) << which;
    const auto width = asDoubleArray(log_.payload(*dims[0]));
    ASSERT_TRUE(width && width->size() == 2) << which;
    const planner::Point2 root(*asDouble(log_.payload(*base_x[0])) - width->front() / 2,
                               *asDouble(log_.payload(*base_y[0])));
    const int n = robot.jointCount();
    std::vector<std::vector<const Record*>> angle_deg, length_m;
    std::string path = m + "Base/";
    for (const planner::ChainJoint& joint : robot.joints) {
      path += joint.name + "/";
      angle_deg.push_back(records(path + "angle", "double"));
      length_m.push_back(records(path + "length", "double"));
      ASSERT_EQ(angle_deg.back().size(), messages.size()) << path;
      ASSERT_EQ(length_m.back().size(), messages.size()) << path;
    }
    double reach_m = 0.0;
    for (const planner::LinkGeometry& link : robot.links) {
      if (link.joint != n - 1) continue;
      for (const planner::ConvexPolygon& p : link.polygons) {
        for (const planner::Point2& v : p.vertices()) reach_m = std::max(reach_m, v.x());
      }
    }
    for (size_t i = 0; i < messages.size(); ++i) {
      const auto frames = planner::linkFrames(robot.joints, jointVector(messages[i].second.position));
      planner::Point2 at = root;
      double heading_rad = 0.0;
      for (int j = 0; j < n; ++j) {
        const auto k = static_cast<size_t>(j);
        heading_rad += *asDouble(log_.payload(*angle_deg[k][i])) * M_PI / 180;
        at += *asDouble(log_.payload(*length_m[k][i])) * planner::Point2(std::cos(heading_rad), std::sin(heading_rad));
        const planner::Point2 end = j + 1 < n ? frames[j].toWorld(robot.joints[j + 1].origin_m)
                                              : frames[j].toWorld(planner::Point2(reach_m, 0.0));
        EXPECT_NEAR(at.x(), end.x(), 1e-9) << which << " ligament " << j << ", record " << i;
        EXPECT_NEAR(at.y(), end.y(), 1e-9) << which << " ligament " << j << ", record " << i;
      }
    }
  }

  static planner::JointVector jointVector(const std::vector<double>& position) {
    planner::JointVector q(static_cast<Eigen::Index>(position.size()));
    for (size_t j = 0; j < position.size(); ++j) q[static_cast<Eigen::Index>(j)] = position[j];
    return q;
  }

  std::filesystem::path path_;
  int64_t events_ = 0;
  Session s_;
  Writer writer_;
  ConvertStats stats_;
  Log log_;
};

class LcmToWpilog : public ::testing::Test, protected ConvertedLog {
 protected:
  void SetUp() override {
    const char* recorded = std::getenv("CYBER_LCM_LOG");
    synthetic_ = recorded == nullptr;
    if (synthetic_) {
      path_ = std::filesystem::temp_directory_path() / ("lcm_to_wpilog_" + std::to_string(getpid()) + ".lcmlog");
      write();
    } else {
      path_ = recorded;
    }
    config_ = config::loadEmbeddedDefaultConfig();
    convert(config_);
  }
  void TearDown() override {
    if (synthetic_) std::filesystem::remove(path_);
  }

  void write() {
    std::mt19937_64 rng(15);
    std::uniform_real_distribution<double> u(-3, 3);
    auto coin = [&] { return (rng() & 1) != 0; };
    lcm::LogFile log(path_.string(), "w");
    ASSERT_TRUE(log.good());
    int64_t t = kSyntheticT0 + kFirstEventLateUs;
    for (int k = 0; k < 12; ++k) {
      const int64_t step_us = k > 0 ? 1000 + static_cast<int64_t>(rng() % 20000) : 0;
      t = k == 1 ? kSyntheticT0 : t + step_us;
      const int64_t utime = t - 300;  // published 300 µs before it was logged
      switch (k % 6) {
        case 0: {
          cyberplanner::arm_state_t m{};
          m.utime = utime;
          m.num_joints = 2;
          m.position.resize(2), m.velocity.resize(2);
          m.position[0] = u(rng), m.position[1] = u(rng), m.velocity[0] = u(rng), m.velocity[1] = u(rng);
          if (coin()) m.pieces.push_back("coral");
          if (coin()) m.pieces.push_back("algae");
          m.num_pieces = static_cast<int8_t>(m.pieces.size());
          event(log, "ARM_STATE", t, m);
          break;
        }
        case 1: {
          cyberplanner::arm_setpoint_t m{};
          m.utime = utime;
          m.mode = static_cast<int8_t>(rng() % 5);
          m.request_id = static_cast<int64_t>(rng() % 100) - 1;
          m.trajectory_t_s = u(rng);
          m.num_joints = 2;
          m.position.resize(2), m.velocity.resize(2), m.volts.resize(2), m.sequence.resize(2);
          for (int j = 0; j < 2; ++j) {
            m.position[j] = u(rng), m.velocity[j] = u(rng), m.volts[j] = u(rng);
            m.sequence[j] = static_cast<uint8_t>(rng());
          }
          event(log, "ARM_SETPOINT", t, m);
          break;
        }
        case 2: {
          cyberplanner::arm_goal_t m{};
          m.utime = utime;
          m.request_id = k;
          m.num_joints = 2;
          m.position.resize(2);
          m.position[0] = u(rng), m.position[1] = u(rng);
          if (coin()) m.pieces.push_back("algae");
          m.num_pieces = static_cast<int8_t>(m.pieces.size());
          m.scene_name = coin() ? "open" : "";
          m.scene_offset_m = coin() ? 0.125 : 0.0;
          event(log, "ARM_GOAL", t, m);
          break;
        }
        case 3: {
          cyberplanner::arm_plan_status_t m{};
          m.utime = utime;
          m.request_id = k;
          m.status = static_cast<int8_t>(rng() % 7);
          m.reason = "reason " + std::to_string(k);
          m.grid_ms = u(rng), m.search_ms = u(rng), m.smooth_ms = u(rng), m.topp_ms = u(rng), m.total_ms = u(rng);
          m.duration_s = u(rng);
          event(log, "ARM_PLAN_STATUS", t, m);
          break;
        }
        case 4:
          event(log, "ARM_TRAJECTORY", t, randomTrajectory(rng, 2, utime, k, 5, [&](size_t) { return u(rng); }));
          break;
        case 5: {
          cyberplanner::arm_daemon_status_t m{};
          m.utime = utime;
          m.mode = static_cast<int8_t>(rng() % 5);
          m.robot_enabled = coin(), m.motion_allowed = coin();
          m.active_request_id = k;
          m.num_joints = 2;
          m.joint_names = {"elevator", "arm"};
          m.joint_units = {"m", "rad"};
          m.state_age_ms = u(rng), m.heartbeat_age_ms = u(rng);
          for (auto* c : {&m.goals_received, &m.plans_succeeded, &m.plans_failed, &m.frames_sent, &m.can_errors,
                          &m.decode_errors, &m.stream_overruns, &m.publish_failures}) {
            *c = static_cast<int64_t>(rng() % 100000);
          }
          m.plan_time_p50_ms = u(rng), m.plan_time_p99_ms = u(rng), m.plan_time_max_ms = u(rng);
          m.stream_jitter_p50_us = u(rng), m.stream_jitter_p99_us = u(rng), m.stream_jitter_max_us = u(rng);
          event(log, "ARM_DAEMON_STATUS", t, m);
          break;
        }
      }
    }
    std::vector<char> garbage{1, 2, 3};
    raw(log, "ARM_STATE", t + 1, garbage);
    raw(log, "SOMETHING_ELSE", t + 2, garbage);
  }

  bool synthetic_ = true;
  config::Config config_;
};

using State = cyberplanner::arm_state_t;
using Setpoint = cyberplanner::arm_setpoint_t;
using Goal = cyberplanner::arm_goal_t;
using PlanStatus = cyberplanner::arm_plan_status_t;
using DaemonStatus = cyberplanner::arm_daemon_status_t;

const char* kModes[] = {"NO_STATE", "HOLDING", "MOVING", "FAULT", "ROBOT_DISABLED"};
const char* kStatuses[] = {"ACCEPTED", "PLANNING", "EXECUTING", "DONE", "REJECTED", "FAILED", "CANCELLED"};

TEST_F(LcmToWpilog, CountsEveryEvent) {
  if (!synthetic_) GTEST_SKIP() << "counts of the synthetic log";
  EXPECT_EQ(stats_.events, 14);
  EXPECT_EQ(stats_.converted, 12);
  EXPECT_EQ(stats_.undecodable, 1);
  EXPECT_EQ(stats_.other, 1);
  EXPECT_EQ(stats_.other_joint_count, 0);
  EXPECT_EQ(log_.extra_header.find("Unix time " + std::to_string(kSyntheticT0)) != std::string::npos, true)
      << log_.extra_header;
  for (const Entry& e : log_.entries) {
    if (e.name.rfind("/.schema/", 0) == 0) continue;
    EXPECT_EQ(e.name.rfind("/CyberPlanner/", 0), 0u) << e.name;
    EXPECT_NE(e.metadata.find("lcm_channel"), std::string::npos) << e.name;
  }
}

// The first event in the file (a state) is 36 µs after the second (a setpoint): the clock starts
// at the setpoint, and the state is 36 µs into it, not clamped to 0.
TEST_F(LcmToWpilog, ClockStartsAtTheEarliestEventNotTheFirstInTheFile) {
  if (!synthetic_) GTEST_SKIP() << "the synthetic log's first two events";
  ASSERT_FALSE(records("Elevator/MeasuredMeters", "double").empty());
  ASSERT_FALSE(records("Elevator/SetpointMeters", "double").empty());
  EXPECT_EQ(records("Elevator/MeasuredMeters", "double").front()->timestamp_us, uint64_t{kFirstEventLateUs});
  EXPECT_EQ(records("Elevator/SetpointMeters", "double").front()->timestamp_us, 0u);
  EXPECT_EQ(stats_.earliest_event_unix_us, static_cast<uint64_t>(kSyntheticT0));
}

TEST_F(LcmToWpilog, MeasuredState) {
  // Entries are named by the config's joints (capitalised) and units: the reference robot's
  // joint 0 is the prismatic "elevator", joint 1 the revolute "arm".
  expectSeries<State, double>(s_.states, "Elevator/MeasuredMeters", [](const State& m) { return m.position[0]; });
  expectSeries<State, double>(s_.states, "Elevator/MeasuredMetersPerSecond",
                              [](const State& m) { return m.velocity[0]; });
  expectSeries<State, double>(s_.states, "Arm/MeasuredRadians", [](const State& m) { return m.position[1]; });
  expectSeries<State, double>(s_.states, "Arm/MeasuredRadiansPerSecond", [](const State& m) { return m.velocity[1]; });
  expectSeries<State, std::string>(s_.states, "State/Pieces", [](const State& m) { return pieceList(m.pieces); });
}

TEST_F(LcmToWpilog, Setpoints) {
  expectSeries<Setpoint, double>(s_.setpoints, "Elevator/SetpointMeters",
                                 [](const Setpoint& m) { return m.position[0]; });
  expectSeries<Setpoint, double>(s_.setpoints, "Elevator/VelocityMetersPerSecond",
                                 [](const Setpoint& m) { return m.velocity[0]; });
  expectSeries<Setpoint, double>(s_.setpoints, "Elevator/FeedforwardVolts",
                                 [](const Setpoint& m) { return m.volts[0]; });
  expectSeries<Setpoint, int64_t>(s_.setpoints, "Elevator/Sequence", [](const Setpoint& m) { return m.sequence[0]; });
  expectSeries<Setpoint, double>(s_.setpoints, "Arm/SetpointRadians", [](const Setpoint& m) { return m.position[1]; });
  expectSeries<Setpoint, double>(s_.setpoints, "Arm/VelocityRadiansPerSecond",
                                 [](const Setpoint& m) { return m.velocity[1]; });
  expectSeries<Setpoint, double>(s_.setpoints, "Arm/FeedforwardVolts", [](const Setpoint& m) { return m.volts[1]; });
  expectSeries<Setpoint, int64_t>(s_.setpoints, "Arm/Sequence", [](const Setpoint& m) { return m.sequence[1]; });
  expectSeries<Setpoint, std::string>(s_.setpoints, "Setpoint/Mode", [](const Setpoint& m) { return kModes[m.mode]; });
  expectSeries<Setpoint, int64_t>(s_.setpoints, "Setpoint/RequestId", [](const Setpoint& m) { return m.request_id; });
  expectSeries<Setpoint, double>(s_.setpoints, "Setpoint/TrajectoryTimeSeconds",
                                 [](const Setpoint& m) { return m.trajectory_t_s; });
}

TEST_F(LcmToWpilog, GoalsAndPlanStatus) {
  expectSeries<Goal, int64_t>(s_.goals, "Goal/RequestId", [](const Goal& m) { return m.request_id; });
  expectSeries<Goal, double>(s_.goals, "Goal/ElevatorMeters", [](const Goal& m) { return m.position[0]; });
  expectSeries<Goal, double>(s_.goals, "Goal/ArmRadians", [](const Goal& m) { return m.position[1]; });
  expectSeries<Goal, std::string>(s_.goals, "Goal/Pieces", [](const Goal& m) { return pieceList(m.pieces); });
  expectSeries<Goal, double>(s_.goals, "Goal/SceneOffsetMeters", [](const Goal& m) { return m.scene_offset_m; });
  expectSeries<Goal, std::string>(s_.goals, "Goal/SceneName", [](const Goal& m) { return m.scene_name; });
  expectSeries<PlanStatus, int64_t>(s_.statuses, "PlanStatus/RequestId",
                                    [](const PlanStatus& m) { return m.request_id; });
  expectSeries<PlanStatus, std::string>(s_.statuses, "PlanStatus/Status",
                                        [](const PlanStatus& m) { return kStatuses[m.status]; });
  expectSeries<PlanStatus, std::string>(s_.statuses, "PlanStatus/Reason", [](const PlanStatus& m) { return m.reason; });
  expectSeries<PlanStatus, double>(s_.statuses, "PlanStatus/GridMs", [](const PlanStatus& m) { return m.grid_ms; });
  expectSeries<PlanStatus, double>(s_.statuses, "PlanStatus/SearchMs", [](const PlanStatus& m) { return m.search_ms; });
  expectSeries<PlanStatus, double>(s_.statuses, "PlanStatus/SmoothMs", [](const PlanStatus& m) { return m.smooth_ms; });
  expectSeries<PlanStatus, double>(s_.statuses, "PlanStatus/ToppMs", [](const PlanStatus& m) { return m.topp_ms; });
  expectSeries<PlanStatus, double>(s_.statuses, "PlanStatus/TotalMs", [](const PlanStatus& m) { return m.total_ms; });
  expectSeries<PlanStatus, double>(s_.statuses, "PlanStatus/DurationSeconds",
                                   [](const PlanStatus& m) { return m.duration_s; });
}

TEST_F(LcmToWpilog, DaemonModeCountersAndTiming) {
  using D = DaemonStatus;
  expectSeries<D, std::string>(s_.daemon, "Daemon/Mode", [](const D& m) { return kModes[m.mode]; });
  expectSeries<D, bool>(s_.daemon, "Daemon/RobotEnabled", [](const D& m) { return m.robot_enabled; });
  expectSeries<D, bool>(s_.daemon, "Daemon/MotionAllowed", [](const D& m) { return m.motion_allowed; });
  expectSeries<D, int64_t>(s_.daemon, "Daemon/ActiveRequestId", [](const D& m) { return m.active_request_id; });
  expectSeries<D, double>(s_.daemon, "Daemon/StateAgeMs", [](const D& m) { return m.state_age_ms; });
  expectSeries<D, double>(s_.daemon, "Daemon/HeartbeatAgeMs", [](const D& m) { return m.heartbeat_age_ms; });
  expectSeries<D, int64_t>(s_.daemon, "Daemon/GoalsReceived", [](const D& m) { return m.goals_received; });
  expectSeries<D, int64_t>(s_.daemon, "Daemon/PlansSucceeded", [](const D& m) { return m.plans_succeeded; });
  expectSeries<D, int64_t>(s_.daemon, "Daemon/PlansFailed", [](const D& m) { return m.plans_failed; });
  expectSeries<D, int64_t>(s_.daemon, "Daemon/FramesSent", [](const D& m) { return m.frames_sent; });
  expectSeries<D, int64_t>(s_.daemon, "Daemon/CanErrors", [](const D& m) { return m.can_errors; });
  expectSeries<D, int64_t>(s_.daemon, "Daemon/DecodeErrors", [](const D& m) { return m.decode_errors; });
  expectSeries<D, int64_t>(s_.daemon, "Daemon/StreamOverruns", [](const D& m) { return m.stream_overruns; });
  expectSeries<D, int64_t>(s_.daemon, "Daemon/PublishFailures", [](const D& m) { return m.publish_failures; });
  expectSeries<D, double>(s_.daemon, "Daemon/PlanTimeP50Ms", [](const D& m) { return m.plan_time_p50_ms; });
  expectSeries<D, double>(s_.daemon, "Daemon/PlanTimeP99Ms", [](const D& m) { return m.plan_time_p99_ms; });
  expectSeries<D, double>(s_.daemon, "Daemon/PlanTimeMaxMs", [](const D& m) { return m.plan_time_max_ms; });
  expectSeries<D, double>(s_.daemon, "Daemon/StreamJitterP50Us", [](const D& m) { return m.stream_jitter_p50_us; });
  expectSeries<D, double>(s_.daemon, "Daemon/StreamJitterP99Us", [](const D& m) { return m.stream_jitter_p99_us; });
  expectSeries<D, double>(s_.daemon, "Daemon/StreamJitterMaxUs", [](const D& m) { return m.stream_jitter_max_us; });
}

TEST_F(LcmToWpilog, TrajectoriesAsArraysAndAsPlannedSeriesOnTheLogClock) {
  using T = cyberplanner::arm_trajectory_t;
  expectSeries<T, int64_t>(s_.trajectories, "Trajectory/RequestId", [](const T& m) { return m.request_id; });
  expectSeries<T, double>(s_.trajectories, "Trajectory/DurationSeconds", [](const T& m) { return m.duration_s; });
  expectSeries<T, double>(s_.trajectories, "Trajectory/StepSeconds", [](const T& m) { return m.dt_s; });
  struct Column {
    const char* name;
    Table table;  // nullptr: t_s
    size_t joint;
  };
  const Column arrays[] = {{"TimesSeconds", nullptr, 0},
                           {"ElevatorMeters", &T::position, 0},
                           {"ElevatorMetersPerSecond", &T::velocity, 0},
                           {"ElevatorVolts", &T::volts, 0},
                           {"ArmRadians", &T::position, 1},
                           {"ArmRadiansPerSecond", &T::velocity, 1},
                           {"ArmVolts", &T::volts, 1}};
  for (const auto& [name, table, joint] : arrays) {
    const auto rs = records(std::string("Trajectory/") + name, "double[]");
    ASSERT_EQ(rs.size(), s_.trajectories.size());
    for (size_t i = 0; i < rs.size(); ++i) {
      const T& m = s_.trajectories[i].second;
      EXPECT_EQ(asDoubleArray(log_.payload(*rs[i])), table ? (m.*table)[joint] : m.t_s) << name;
    }
  }
  // Sample k is commanded at start_utime + t_s[k], which is (start_utime - utime) after the
  // message's own time (5 ms in the synthetic log), until the next trajectory starts.
  const Column planned[] = {
      {"Elevator/PlannedMeters", &T::position, 0},      {"Elevator/PlannedMetersPerSecond", &T::velocity, 0},
      {"Elevator/PlannedVolts", &T::volts, 0},          {"Arm/PlannedRadians", &T::position, 1},
      {"Arm/PlannedRadiansPerSecond", &T::velocity, 1}, {"Arm/PlannedVolts", &T::volts, 1}};
  for (const auto& [name, table, joint] : planned) {
    const size_t replaced = expectPlanned(name, table, joint);
    if (synthetic_) {
      EXPECT_GT(replaced, 0u) << "the synthetic trajectories should overlap";
    }
  }
  const auto start = records("Trajectory/StartSeconds", "double");
  ASSERT_EQ(start.size(), s_.trajectories.size());
  const auto& [t, first] = s_.trajectories.front();
  EXPECT_DOUBLE_EQ(*asDouble(log_.payload(*start[0])),
                   static_cast<double>(t - s_.t0 + first.start_utime - first.utime) * 1e-6);
}

// The reference robot as docs/operations.md promises it: the 3-D components are the carriage
// (unturned) at the pivot and the arm turned by its angle about the pivot, as planner::linkFrames
// places them; the Mechanism2d ligaments, named by the joints, are the rail as long as the
// carriage's travel and the arm, adding up to the arm's angle.
TEST_F(LcmToWpilog, MechanismFollowsTheMeasuredState) {
  const auto poses = records("Mechanism3d/Measured", "struct:Pose3d[]");
  ASSERT_EQ(poses.size(), s_.states.size());
  ASSERT_TRUE(log_.find("/.schema/struct:Pose3d"));
  const auto rail = records("Mechanism2d/Measured/Base/elevator/angle", "double");
  const auto arm = records("Mechanism2d/Measured/Base/elevator/arm/angle", "double");
  const auto length = records("Mechanism2d/Measured/Base/elevator/length", "double");
  ASSERT_EQ(rail.size(), poses.size());
  ASSERT_EQ(arm.size(), poses.size());
  ASSERT_EQ(length.size(), poses.size());
  EXPECT_EQ(asString(log_.payload(*records("Mechanism2d/Measured/.type", "string").front())), "Mechanism2d");
  for (size_t i = 0; i < poses.size(); ++i) {
    const State& m = s_.states[i].second;
    const planner::LinkFrame pose = planner::linkFrames(config_.robot.joints, jointVector(m.position))[1];
    std::vector<Pose3d> p;
    ASSERT_TRUE(unpackPose3dArray(log_.payload(*poses[i]), &p));
    ASSERT_EQ(p.size(), 2u);
    for (const Pose3d& c : p) {
      EXPECT_NEAR(c.x, pose.origin_m.x(), 1e-12);
      EXPECT_NEAR(c.z, pose.origin_m.y(), 1e-12);
      EXPECT_EQ(c.y, 0.0);
    }
    EXPECT_EQ(p[0].qw, 1.0);
    EXPECT_NEAR((*asDouble(log_.payload(*rail[i])) + *asDouble(log_.payload(*arm[i]))) * M_PI / 180, m.position[1],
                1e-12);
    EXPECT_EQ(asDouble(log_.payload(*length[i])), m.position[0]);
  }
  expectPoses("Measured", s_.states, config_.robot.joints);
  expectPoses("Setpoint", s_.setpoints, config_.robot.joints);
  expectLigaments("Measured", s_.states, config_.robot);
  expectLigaments("Setpoint", s_.setpoints, config_.robot);
}

TEST(LcmToWpilogErrors, MissingAndForeignLogsAreErrors) {
  const config::ChannelNames channels;
  const auto missing = convertLcmLog("/nonexistent.lcmlog", channels, {});
  ASSERT_EQ(missing.status(), WpilogStatus::kCannotOpen);
  EXPECT_NE(missing.error().message.find("cannot open"), std::string::npos);
  const auto path = std::filesystem::temp_directory_path() / ("foreign_" + std::to_string(getpid()) + ".lcmlog");
  {
    lcm::LogFile log(path.string(), "w");
    std::vector<char> bytes{1, 2, 3};
    lcm::LogEvent e{};
    e.channel = "ARM_GOAL";
    e.datalen = 3;
    e.data = bytes.data();
    ASSERT_EQ(log.writeEvent(&e), 0);
  }
  const auto foreign = convertLcmLog(path.string(), channels, {});
  ASSERT_EQ(foreign.status(), WpilogStatus::kNoMessages);
  EXPECT_NE(foreign.error().message.find("1 undecodable"), std::string::npos) << foreign.error().message;
  std::filesystem::remove(path);
}

// A named goal carries its name and no values; a message of another joint count than the config's
// is another robot's and is not read as this one's (docs/lcm.md, "Joints by index").
TEST(LcmToWpilogJoints, NamedGoalsGiveTheirNameAndOtherJointCountsAreSkipped) {
  const auto path = std::filesystem::temp_directory_path() / ("named_" + std::to_string(getpid()) + ".lcmlog");
  {
    lcm::LogFile log(path.string(), "w");
    int64_t eventnum = 0;
    auto put = [&](const std::string& channel, const auto& m) {
      std::vector<char> bytes(static_cast<size_t>(m.getEncodedSize()));
      m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
      lcm::LogEvent e{};
      e.eventnum = eventnum++;
      e.timestamp = kSyntheticT0 + eventnum * 1000;
      e.channel = channel;
      e.datalen = static_cast<int32_t>(bytes.size());
      e.data = bytes.data();
      ASSERT_EQ(log.writeEvent(&e), 0);
    };
    cyberplanner::arm_goal_t goal{};
    goal.request_id = 3;
    goal.pose_name = "L3";
    put("ARM_GOAL", goal);
    cyberplanner::arm_state_t three{};
    three.num_joints = 3;
    three.position = {0.1, 0.2, 0.3};
    three.velocity = {0.0, 0.0, 0.0};
    put("ARM_STATE", three);
  }
  const config::Config config = config::loadEmbeddedDefaultConfig();
  auto conversion = convertLcmLog(path.string(), config.daemon.channels, mechanismGeometry(config.robot));
  std::filesystem::remove(path);
  ASSERT_TRUE(conversion.ok()) << conversion.error().message;
  auto log = parse(conversion.value().writer.bytes());
  ASSERT_TRUE(log.ok()) << log.error().message;
  const auto name = log.value().find("/CyberPlanner/Goal/PoseName");
  ASSERT_TRUE(name);
  EXPECT_EQ(log.value().entries[*name].type, "string");
  EXPECT_TRUE(log.value().find("/CyberPlanner/Goal/RequestId"));
  EXPECT_FALSE(log.value().find("/CyberPlanner/Goal/ElevatorMeters")) << "a named goal has no values";
  EXPECT_FALSE(log.value().find("/CyberPlanner/Elevator/MeasuredMeters")) << "a 3-joint state is not this robot's";
  EXPECT_EQ(conversion.value().stats.other_joint_count, 1) << "the 3-joint state, not the named goal";
}

// A robot whose chain the conversion is tested on: a shipped config/ file, or one built here.
struct ChainCase {
  const char* name;  // the GoogleTest parameter name
  std::function<config::Config()> load;
};

config::Config shippedConfig(const std::string& file) {
  return config::loadConfigFile(std::string(CYBER_SOURCE_DIR) + "/config/" + file);
}

planner::ConvexPolygon box(double x0_m, double y0_m, double x1_m, double y1_m) {
  return planner::ConvexPolygon::fromVertices({{x0_m, y0_m}, {x1_m, y0_m}, {x1_m, y1_m}, {x0_m, y1_m}}).value();
}

// A chain none of the shipped robots has: a shoulder whose slide sits off its link's axis and
// slides at an angle to it, and a wrist off the slide's axis, so that every joint's origin and
// axis count.
config::Config offsetChain() {
  config::Config config;
  planner::RobotModel& robot = config.robot;
  robot.name = "offset-chain";
  robot.joints.push_back({"shoulder", planner::JointType::kRevolute, planner::Point2(-0.1, 0.5), 0.2, {-1.0, 2.0}});
  robot.joints.push_back({"slide", planner::JointType::kPrismatic, planner::Point2(0.3, 0.08), 0.5, {-0.1, 0.4}});
  robot.joints.push_back({"wrist", planner::JointType::kRevolute, planner::Point2(0.2, -0.05), -0.3, {-2.0, 2.0}});
  robot.links.push_back({"upper", 0, {box(-0.05, -0.04, 0.4, 0.04)}});
  robot.links.push_back({"slider", 1, {box(-0.1, -0.03, 0.3, 0.03)}});
  robot.links.push_back({"hand", 2, {box(-0.02, -0.05, 0.22, 0.05), box(0.1, 0.0, 0.27, 0.02)}});
  return config;
}

// The parameter's name in test listings.
void PrintTo(const ChainCase& chain, std::ostream* os) { *os << chain.name; }

const ChainCase kChains[] = {
    {"one_joint_intake_pivot", [] { return shippedConfig("intake-pivot.toml"); }},
    {"two_joints_reference", [] { return shippedConfig("reefscape-2025.toml"); }},
    {"two_joints_double_jointed", [] { return shippedConfig("chargedup-2023-double-jointed.toml"); }},
    {"two_joints_pivot_telescope", [] { return shippedConfig("pivot-telescope.toml"); }},
    {"three_joints_elevator_pivot_wrist", [] { return shippedConfig("reefscape-2025-elevator-pivot-wrist.toml"); }},
    {"three_joints_offset", offsetChain},
};

// "elevator" -> "Elevator", as cyber-wpilog names a joint's entries.
std::string capitalised(std::string name) {
  if (!name.empty() && name[0] >= 'a' && name[0] <= 'z') name[0] = static_cast<char>(name[0] - 'a' + 'A');
  return name;
}

// A session of the robot's N joints: states, setpoints, goals (one of them named) and
// overlapping trajectories, each with N values per joint array, at positions across the joints'
// ranges; and a state of another joint count, which is another robot's.
class LcmToWpilogChains : public ::testing::TestWithParam<ChainCase>, protected ConvertedLog {
 protected:
  void SetUp() override {
    ASSERT_NO_THROW(config_ = GetParam().load()) << GetParam().name;
    n_ = config_.robot.jointCount();
    ASSERT_GE(n_, 1);
    path_ = std::filesystem::temp_directory_path() /
            ("lcm_to_wpilog_" + std::string(GetParam().name) + "_" + std::to_string(getpid()) + ".lcmlog");
    write();
    convert(config_);
    // The messages of this robot's joint count: all but the other robot's state.
    std::erase_if(s_.states, [&](const auto& m) { return m.second.num_joints != n_; });
    ASSERT_EQ(s_.states.size(), 4u);
  }
  void TearDown() override { std::filesystem::remove(path_); }

  void write() {
    std::mt19937_64 rng(34);
    const auto n = static_cast<size_t>(n_);
    const auto within = [&](size_t j) {
      const planner::JointRange& r = config_.robot.range(static_cast<int>(j));
      return std::uniform_real_distribution<double>(r.min, r.max)(rng);
    };
    std::uniform_real_distribution<double> u(-3, 3);
    lcm::LogFile log(path_.string(), "w");
    ASSERT_TRUE(log.good());
    int64_t t = kSyntheticT0;
    for (int k = 0; k < 16; ++k) {
      t += k > 0 ? 1000 + static_cast<int64_t>(rng() % 20000) : 0;
      const int64_t utime = t - 300;
      switch (k % 4) {
        case 0: {
          cyberplanner::arm_state_t m{};
          m.utime = utime;
          m.num_joints = static_cast<int8_t>(n);
          for (size_t j = 0; j < n; ++j) m.position.push_back(within(j)), m.velocity.push_back(u(rng));
          event(log, "ARM_STATE", t, m);
          break;
        }
        case 1: {
          cyberplanner::arm_setpoint_t m{};
          m.utime = utime;
          m.mode = 2;
          m.request_id = k;
          m.num_joints = static_cast<int8_t>(n);
          for (size_t j = 0; j < n; ++j) {
            m.position.push_back(within(j)), m.velocity.push_back(u(rng)), m.volts.push_back(u(rng));
            m.sequence.push_back(static_cast<uint8_t>(rng()));
          }
          event(log, "ARM_SETPOINT", t, m);
          break;
        }
        case 2: {
          cyberplanner::arm_goal_t m{};
          m.utime = utime;
          m.request_id = k;
          if (k == 2) {
            m.pose_name = "STOW";  // a named goal: no values
          } else {
            m.num_joints = static_cast<int8_t>(n);
            for (size_t j = 0; j < n; ++j) m.position.push_back(within(j));
          }
          event(log, "ARM_GOAL", t, m);
          break;
        }
        case 3: event(log, "ARM_TRAJECTORY", t, randomTrajectory(rng, n, utime, k, 10, within)); break;
      }
    }
    cyberplanner::arm_state_t other{};
    other.num_joints = static_cast<int8_t>(n % planner::kMaxJoints + 1);
    other.position.assign(static_cast<size_t>(other.num_joints), 0.25);
    other.velocity.assign(static_cast<size_t>(other.num_joints), 0.0);
    event(log, "ARM_STATE", t + 1000, other);
  }

  config::Config config_;
  int n_ = 0;
};

TEST_P(LcmToWpilogChains, EachJointHasItsEntriesByTheConfigsName) {
  using T = cyberplanner::arm_trajectory_t;
  std::vector<std::pair<int64_t, Goal>> goals;  // those with values
  std::copy_if(s_.goals.begin(), s_.goals.end(), std::back_inserter(goals),
               [](const auto& m) { return m.second.pose_name.empty(); });
  ASSERT_EQ(goals.size(), 3u);
  std::set<std::string> expected_joints;
  for (int j = 0; j < n_; ++j) {
    const planner::ChainJoint& joint = config_.robot.joints[j];
    const std::string name = capitalised(joint.name);
    const bool slides = joint.type == planner::JointType::kPrismatic;
    const std::string unit = slides ? "Meters" : "Radians";
    const std::string rate = slides ? "MetersPerSecond" : "RadiansPerSecond";
    const auto k = static_cast<size_t>(j);
    expected_joints.insert(name);
    expectSeries<State, double>(s_.states, name + "/Measured" + unit, [k](const State& m) { return m.position[k]; });
    expectSeries<State, double>(s_.states, name + "/Measured" + rate, [k](const State& m) { return m.velocity[k]; });
    expectSeries<Setpoint, double>(s_.setpoints, name + "/Setpoint" + unit,
                                   [k](const Setpoint& m) { return m.position[k]; });
    expectSeries<Setpoint, double>(s_.setpoints, name + "/Velocity" + rate,
                                   [k](const Setpoint& m) { return m.velocity[k]; });
    expectSeries<Setpoint, double>(s_.setpoints, name + "/FeedforwardVolts",
                                   [k](const Setpoint& m) { return m.volts[k]; });
    expectSeries<Setpoint, int64_t>(s_.setpoints, name + "/Sequence", [k](const Setpoint& m) { return m.sequence[k]; });
    expectSeries<Goal, double>(goals, "Goal/" + name + unit, [k](const Goal& m) { return m.position[k]; });
    const std::pair<std::string, Table> columns[] = {{unit, &T::position}, {rate, &T::velocity}, {"Volts", &T::volts}};
    for (const auto& [suffix, table] : columns) {
      const auto rs = records("Trajectory/" + name + suffix, "double[]");
      ASSERT_EQ(rs.size(), s_.trajectories.size());
      for (size_t i = 0; i < rs.size(); ++i) {
        EXPECT_EQ(asDoubleArray(log_.payload(*rs[i])), (s_.trajectories[i].second.*table)[k]) << name << suffix;
      }
    }
    EXPECT_GT(expectPlanned(name + "/Planned" + unit, &T::position, k), 0u) << "the trajectories should overlap";
    expectPlanned(name + "/Planned" + rate, &T::velocity, k);
    expectPlanned(name + "/PlannedVolts", &T::volts, k);
  }
  EXPECT_EQ(stats_.other_joint_count, 1) << "the other robot's state";
  // No joint the robot does not have: every joint's setpoints carry a Sequence entry.
  std::set<std::string> joints;
  for (const Entry& e : log_.entries) {
    const std::string suffix = "/Sequence";
    if (e.name.size() > suffix.size() && e.name.ends_with(suffix)) {
      joints.insert(e.name.substr(std::string("/CyberPlanner/").size(),
                                  e.name.size() - suffix.size() - std::string("/CyberPlanner/").size()));
    }
  }
  EXPECT_EQ(joints, expected_joints);
}

TEST_P(LcmToWpilogChains, APosePerLinkAtItsFrame) {
  expectPoses("Measured", s_.states, config_.robot.joints);
  expectPoses("Setpoint", s_.setpoints, config_.robot.joints);
}

TEST_P(LcmToWpilogChains, LigamentsEndWhereTheNextJointSits) {
  expectLigaments("Measured", s_.states, config_.robot);
  expectLigaments("Setpoint", s_.setpoints, config_.robot);
  // The links that carry another joint are blue; the last is the colour of its entry.
  std::string path = "Mechanism2d/Measured/Base/";
  for (int j = 0; j < n_; ++j) {
    path += config_.robot.joints[j].name + "/";
    const auto color = records(path + "color", "string");
    ASSERT_EQ(color.size(), 1u) << path;
    EXPECT_EQ(asString(log_.payload(*color[0])), j + 1 < n_ ? "#3070FF" : "#FF8020") << path;
  }
}

INSTANTIATE_TEST_SUITE_P(Chains, LcmToWpilogChains, ::testing::ValuesIn(kChains),
                         [](const ::testing::TestParamInfo<ChainCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace cyber::wpilog

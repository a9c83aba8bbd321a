#include "cyber/wpilog/lcm_to_wpilog.hpp"

#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>

#include "cyber/lcmtypes/constant_names.hpp"
#include "cyber/lcmtypes/safe_decode.hpp"
#include "cyber/wpilog/pose3d.hpp"
#include "cyberplanner/arm_daemon_status_t.hpp"
#include "cyberplanner/arm_goal_t.hpp"
#include "cyberplanner/arm_plan_status_t.hpp"
#include "cyberplanner/arm_setpoint_t.hpp"
#include "cyberplanner/arm_state_t.hpp"
#include "cyberplanner/arm_trajectory_t.hpp"

namespace cyber::wpilog {
namespace {

constexpr const char* kRoot = "/CyberPlanner/";
constexpr double kRadToDeg = 180.0 / M_PI;

// Entries are started on first use, each with the LCM channel it comes from as metadata.
class Entries {
 public:
  explicit Entries(Writer& writer) : writer_(writer) {}
  void setChannel(const std::string& channel) {
    metadata_ = R"({"source":"cyber-wpilog","lcm_channel":")" + channel + "\"}";
  }

  void putDouble(const std::string& name, uint64_t t, double v) { writer_.appendDouble(id(name, "double", t), t, v); }
  void putInt64(const std::string& name, uint64_t t, int64_t v) { writer_.appendInt64(id(name, "int64", t), t, v); }
  void putBoolean(const std::string& name, uint64_t t, bool v) { writer_.appendBoolean(id(name, "boolean", t), t, v); }
  void putString(const std::string& name, uint64_t t, const std::string& v) {
    writer_.appendString(id(name, "string", t), t, v);
  }
  void putDoubles(const std::string& name, uint64_t t, const std::vector<double>& v) {
    writer_.appendDoubleArray(id(name, "double[]", t), t, v);
  }
  void putPoses(const std::string& name, uint64_t t, std::span<const Pose3d> poses) {
    if (!pose_schemas_) {
      addPose3dSchemas(writer_, t);
      pose_schemas_ = true;
    }
    writer_.appendRaw(id(name, "struct:Pose3d[]", t), t, packPose3dArray(poses));
  }
  [[nodiscard]] bool started(const std::string& name) const { return ids_.contains(kRoot + name); }

 private:
  uint32_t id(const std::string& name, const char* type, uint64_t t) {
    const std::string full = kRoot + name;
    const auto it = ids_.find(full);
    if (it != ids_.end()) return it->second;
    const uint32_t id = writer_.start(full, type, metadata_, t);
    ids_.emplace(full, id);
    return id;
  }

  Writer& writer_;
  std::string metadata_;
  std::map<std::string, uint32_t> ids_;
  bool pose_schemas_ = false;
};

// Entry names of a joint: its config name capitalised ("elevator" -> "Elevator") and its unit.
struct JointNames {
  std::string joint;     // "Elevator", "Shoulder", ...
  std::string position;  // "Meters" (prismatic) / "Radians" (revolute)
  std::string velocity;  // "MetersPerSecond" / "RadiansPerSecond"
};

JointNames jointNames(const planner::ChainJoint& joint) {
  std::string name = joint.name;
  if (!name.empty() && name[0] >= 'a' && name[0] <= 'z') name[0] = static_cast<char>(name[0] - 'a' + 'A');
  const bool slides = joint.type == planner::JointType::kPrismatic;
  return JointNames{name, slides ? "Meters" : "Radians", slides ? "MetersPerSecond" : "RadiansPerSecond"};
}

std::string key(const JointNames& j, const std::string& what) { return j.joint + "/" + what; }

// Held pieces as one string: the names joined by ',' ("none" for none).
std::string pieceList(const std::vector<std::string>& pieces) {
  std::string out;
  for (const auto& piece : pieces) out += (out.empty() ? "" : ",") + piece;
  return out.empty() ? "none" : out;
}

class Converter {
 public:
  Converter(Entries& entries, const MechanismGeometry& geometry)
      : e_(entries), g_(geometry), j_{jointNames(geometry.chain[0]), jointNames(geometry.chain[1])} {}

  // A state or setpoint of another joint count than the config's is of another robot: skipped, as
  // the daemon ignores such a state (docs/lcm.md, "Joints by index").
  void state(uint64_t t, const cyberplanner::arm_state_t& m) {
    if (!ours(m.num_joints)) return;
    for (size_t j = 0; j < j_.size(); ++j) {
      e_.putDouble(key(j_[j], "Measured" + j_[j].position), t, m.position[j]);
      e_.putDouble(key(j_[j], "Measured" + j_[j].velocity), t, m.velocity[j]);
    }
    e_.putString("State/Pieces", t, pieceList(m.pieces));
    mechanism("Measured", t, m.position[0], m.position[1]);
  }

  void setpoint(uint64_t t, const cyberplanner::arm_setpoint_t& m) {
    if (!ours(m.num_joints)) return;
    for (size_t j = 0; j < j_.size(); ++j) joint(j_[j], t, m.position[j], m.velocity[j], m.volts[j], m.sequence[j]);
    e_.putString("Setpoint/Mode", t, lcmtypes::modeName(m.mode));
    e_.putInt64("Setpoint/RequestId", t, m.request_id);
    e_.putDouble("Setpoint/TrajectoryTimeSeconds", t, m.trajectory_t_s);
    mechanism("Setpoint", t, m.position[0], m.position[1]);
  }

  void goal(uint64_t t, const cyberplanner::arm_goal_t& m) {
    e_.putInt64("Goal/RequestId", t, m.request_id);
    // A named goal sends no values (docs/lcm.md, "Named goals"): its name is the target.
    if (!m.pose_name.empty()) e_.putString("Goal/PoseName", t, m.pose_name);
    if (ours(m.num_joints)) {
      for (size_t j = 0; j < j_.size(); ++j) e_.putDouble("Goal/" + j_[j].joint + j_[j].position, t, m.position[j]);
    }
    e_.putString("Goal/Pieces", t, pieceList(m.pieces));
    e_.putString("Goal/SceneName", t, m.scene_name);
    e_.putDouble("Goal/SceneOffsetMeters", t, m.scene_offset_m);
  }

  void planStatus(uint64_t t, const cyberplanner::arm_plan_status_t& m) {
    e_.putInt64("PlanStatus/RequestId", t, m.request_id);
    e_.putString("PlanStatus/Status", t, lcmtypes::statusName(m.status));
    e_.putString("PlanStatus/Reason", t, m.reason);
    e_.putDouble("PlanStatus/GridMs", t, m.grid_ms);
    e_.putDouble("PlanStatus/SearchMs", t, m.search_ms);
    e_.putDouble("PlanStatus/SmoothMs", t, m.smooth_ms);
    e_.putDouble("PlanStatus/ToppMs", t, m.topp_ms);
    e_.putDouble("PlanStatus/TotalMs", t, m.total_ms);
    e_.putDouble("PlanStatus/DurationSeconds", t, m.duration_s);
  }

  // The whole trajectory as arrays at its arrival, and its samples as the planned series of
  // each joint at the times they are commanded.
  void trajectory(uint64_t t, const cyberplanner::arm_trajectory_t& m) {
    if (!ours(m.num_joints)) return;
    const int64_t start_us = static_cast<int64_t>(t) + (m.start_utime - m.utime);
    e_.putInt64("Trajectory/RequestId", t, m.request_id);
    e_.putDouble("Trajectory/DurationSeconds", t, m.duration_s);
    e_.putDouble("Trajectory/StepSeconds", t, m.dt_s);
    e_.putDouble("Trajectory/StartSeconds", t, static_cast<double>(start_us) * 1e-6);
    e_.putDoubles("Trajectory/TimesSeconds", t, m.t_s);
    // position, velocity and volts are [joint][sample]; a row a decoder did not fill is empty.
    const auto row = [](const std::vector<std::vector<double>>& table, size_t j) {
      return j < table.size() ? table[j] : std::vector<double>{};
    };
    size_t n = m.t_s.size();
    for (size_t j = 0; j < j_.size(); ++j) {
      const std::string& name = j_[j].joint;
      e_.putDoubles("Trajectory/" + name + j_[j].position, t, row(m.position, j));
      e_.putDoubles("Trajectory/" + name + j_[j].velocity, t, row(m.velocity, j));
      e_.putDoubles("Trajectory/" + name + "Volts", t, row(m.volts, j));
      n = std::min({n, row(m.position, j).size(), row(m.velocity, j).size(), row(m.volts, j).size()});
    }
    // A new trajectory replaces the rest of the one before from its start on (docs/lcm.md: a goal
    // during motion is spliced in), so each planned entry stays in time order.
    while (!planned_.empty() && planned_.back().t_us >= start_us) planned_.pop_back();
    for (size_t k = 0; k < n; ++k) {
      const int64_t at = start_us + std::llround(m.t_s[k] * 1e6);
      if (at < 0) continue;
      PlannedSample sample{at, m.request_id, {}};
      for (size_t j = 0; j < j_.size(); ++j) sample.joints[j] = {m.position[j][k], m.velocity[j][k], m.volts[j][k]};
      planned_.push_back(sample);
    }
  }

  // Writes the planned series, once every trajectory of the log is known.
  void finish() {
    for (const PlannedSample& p : planned_) {
      const auto ts = static_cast<uint64_t>(p.t_us);
      e_.setChannel(channel_of_trajectories_);
      for (size_t j = 0; j < j_.size(); ++j) planned(j_[j], ts, p.joints[j][0], p.joints[j][1], p.joints[j][2]);
      e_.putInt64("Planned/RequestId", ts, p.request_id);
    }
    planned_.clear();
  }
  void setTrajectoryChannel(const std::string& channel) { channel_of_trajectories_ = channel; }

  void daemonStatus(uint64_t t, const cyberplanner::arm_daemon_status_t& m) {
    e_.putString("Daemon/Mode", t, lcmtypes::modeName(m.mode));
    e_.putBoolean("Daemon/RobotEnabled", t, m.robot_enabled);
    e_.putBoolean("Daemon/MotionAllowed", t, m.motion_allowed);
    e_.putInt64("Daemon/ActiveRequestId", t, m.active_request_id);
    e_.putDouble("Daemon/StateAgeMs", t, m.state_age_ms);
    e_.putDouble("Daemon/HeartbeatAgeMs", t, m.heartbeat_age_ms);
    const std::pair<const char*, int64_t> counters[] = {
        {"GoalsReceived", m.goals_received},   {"PlansSucceeded", m.plans_succeeded},
        {"PlansFailed", m.plans_failed},       {"FramesSent", m.frames_sent},
        {"CanErrors", m.can_errors},           {"DecodeErrors", m.decode_errors},
        {"StreamOverruns", m.stream_overruns}, {"PublishFailures", m.publish_failures}};
    for (const auto& [name, value] : counters) e_.putInt64(std::string("Daemon/") + name, t, value);
    const std::pair<const char*, double> timings[] = {
        {"PlanTimeP50Ms", m.plan_time_p50_ms},         {"PlanTimeP99Ms", m.plan_time_p99_ms},
        {"PlanTimeMaxMs", m.plan_time_max_ms},         {"StreamJitterP50Us", m.stream_jitter_p50_us},
        {"StreamJitterP99Us", m.stream_jitter_p99_us}, {"StreamJitterMaxUs", m.stream_jitter_max_us}};
    for (const auto& [name, value] : timings) e_.putDouble(std::string("Daemon/") + name, t, value);
  }

 private:
  [[nodiscard]] bool ours(int num_joints) const { return num_joints == static_cast<int>(j_.size()); }

  void joint(const JointNames& j, uint64_t t, double q, double v, double volts, uint8_t sequence) {
    e_.putDouble(key(j, "Setpoint" + j.position), t, q);
    e_.putDouble(key(j, "Velocity" + j.velocity), t, v);
    e_.putDouble(key(j, "FeedforwardVolts"), t, volts);
    e_.putInt64(key(j, "Sequence"), t, sequence);
  }

  void planned(const JointNames& j, uint64_t t, double q, double v, double volts) {
    e_.putDouble(key(j, "Planned" + j.position), t, q);
    e_.putDouble(key(j, "Planned" + j.velocity), t, v);
    e_.putDouble(key(j, "PlannedVolts"), t, volts);
  }

  // The mechanism as AdvantageScope draws logged mechanisms: a Mechanism2d (one ligament per joint,
  // named as the robot description names it, angles in degrees, each relative to its parent) and
  // each link frame's robot-frame pose as a 3-D component (x forward, z up; the side view's y is z).
  void mechanism(const std::string& which, uint64_t t, double q0, double q1) {
    const planner::JointVector q(q0, q1);
    const std::string m = "Mechanism2d/" + which + "/";
    const std::string first = m + "Base/" + g_.chain[0].name + "/";
    const std::string second = first + g_.chain[1].name + "/";
    if (!e_.started(m + ".type")) {
      e_.putString(m + ".type", t, "Mechanism2d");
      e_.putBoolean(m + ".controllable", t, false);
      e_.putDoubles(m + "dims", t, {kMechanismWidthM, kMechanismHeightM});
      e_.putString(m + "backgroundColor", t, "#000020");
      e_.putDouble(m + "Base/x", t, g_.chain[0].origin_m.x() + kMechanismOriginXM);
      e_.putDouble(m + "Base/y", t, g_.chain[0].origin_m.y());
      e_.putString(first + ".type", t, "line");
      e_.putString(first + "color", t, "#3070FF");
      e_.putDouble(first + "weight", t, 8.0);
      e_.putString(second + ".type", t, "line");
      e_.putString(second + "color", t, which == "Measured" ? "#FF8020" : "#20FF80");
      e_.putDouble(second + "weight", t, 6.0);
    }
    // A ligament points along its link's x axis (a prismatic joint's along its travel) and is as
    // long as the travel (prismatic) or the link's outline (revolute). Angles are summed along the
    // chain, not wrapped: a ligament turns on as its joint does.
    const auto frames = planner::linkFrames(g_.chain, q);
    std::array<double, planner::kJointCount> angle_rad{}, length_m{};
    double parent_rad = 0.0;
    for (int j = 0; j < planner::kJointCount; ++j) {
      const planner::ChainJoint& joint = g_.chain[static_cast<size_t>(j)];
      const bool slides = joint.type == planner::JointType::kPrismatic;
      angle_rad[static_cast<size_t>(j)] = parent_rad + joint.axis_rad + (slides ? 0.0 : q[j]);
      length_m[static_cast<size_t>(j)] = (slides ? q[j] : 0.0) + g_.link_length_m[static_cast<size_t>(j)];
      if (!slides) parent_rad = angle_rad[static_cast<size_t>(j)];
    }
    e_.putDouble(first + "angle", t, angle_rad[0] * kRadToDeg);
    e_.putDouble(first + "length", t, length_m[0]);
    e_.putDouble(second + "angle", t, (angle_rad[1] - angle_rad[0]) * kRadToDeg);
    e_.putDouble(second + "length", t, length_m[1]);

    // A rotation by -angle about +y turns +x up toward +z by angle.
    std::array<Pose3d, planner::kJointCount> poses;
    for (size_t k = 0; k < poses.size(); ++k) {
      const double a = frames[k].angle_rad();
      poses[k] = Pose3d{frames[k].origin_m.x(), 0, frames[k].origin_m.y(), std::cos(-a / 2), 0, std::sin(-a / 2), 0};
    }
    e_.putPoses("Mechanism3d/" + which, t, poses);
  }

  // The Mechanism2d canvas: a side view from 1.5 m behind the robot's origin to 1.5 m past it.
  static constexpr double kMechanismOriginXM = 1.5;
  static constexpr double kMechanismWidthM = 3.0;
  static constexpr double kMechanismHeightM = 2.6;

  struct PlannedSample {
    int64_t t_us;
    int64_t request_id;
    std::array<std::array<double, 3>, planner::kJointCount> joints;  // position, velocity, feedforward volts
  };

  Entries& e_;
  const MechanismGeometry& g_;
  std::array<JointNames, planner::kJointCount> j_;
  std::vector<PlannedSample> planned_;
  std::string channel_of_trajectories_;
};

struct Event {
  std::string channel;
  int64_t timestamp_us;
  std::vector<uint8_t> data;
};

template <typename Message>
bool decode(const Event& event, Message* m) {
  return lcmtypes::safeDecode(*m, event.data.data(), static_cast<int>(event.data.size())) >= 0;
}

}  // namespace

MechanismGeometry mechanismGeometry(const planner::RobotModel& robot) {
  MechanismGeometry g;
  g.chain = robot.joints;
  for (const planner::LinkGeometry& link : robot.links) {
    for (const planner::ConvexPolygon& p : link.polygons) {
      for (const planner::Point2& v : p.vertices()) {
        double& length = g.link_length_m[static_cast<size_t>(link.joint)];
        length = std::max(length, v.x());
      }
    }
  }
  // A revolute link that carries the next joint reaches at least to it.
  for (int j = 0; j + 1 < planner::kJointCount; ++j) {
    if (g.chain[static_cast<size_t>(j)].type == planner::JointType::kRevolute) {
      double& length = g.link_length_m[static_cast<size_t>(j)];
      length = std::max(length, g.chain[static_cast<size_t>(j) + 1].origin_m.x());
    }
  }
  // A prismatic link's ligament is its travel alone (the carriage's outline is not along it).
  for (int j = 0; j < planner::kJointCount; ++j) {
    if (g.chain[static_cast<size_t>(j)].type == planner::JointType::kPrismatic)
      g.link_length_m[static_cast<size_t>(j)] = 0;
  }
  return g;
}

Result<Conversion, WpilogStatus> convertLcmLog(const std::string& lcm_path, const config::ChannelNames& channels,
                                               const MechanismGeometry& geometry) {
  lcm::LogFile log(lcm_path, "r");
  if (!log.good()) {
    return Result<Conversion, WpilogStatus>::failure(WpilogStatus::kCannotOpen, lcm_path + ": cannot open the LCM log");
  }
  std::vector<Event> events;
  for (const lcm::LogEvent* e = log.readNextEvent(); e != nullptr; e = log.readNextEvent()) {
    const auto* bytes = static_cast<const uint8_t*>(e->data);
    events.push_back(Event{e->channel, e->timestamp, std::vector<uint8_t>(bytes, bytes + e->datalen)});
  }
  // lcm-logger can write an event before one it received a few µs earlier (a recording started
  // ARM_GOAL, then ARM_STATE 36 µs older), so the clock starts at the earliest event and the
  // events are converted in time order: every record at its true offset, each entry in order.
  std::stable_sort(events.begin(), events.end(),
                   [](const Event& a, const Event& b) { return a.timestamp_us < b.timestamp_us; });
  ConvertStats s;
  s.events = static_cast<int64_t>(events.size());
  s.earliest_event_unix_us = events.empty() ? 0 : static_cast<uint64_t>(events.front().timestamp_us);
  Writer writer("cyber-wpilog " + lcm_path + "; t = 0 is Unix time " + std::to_string(s.earliest_event_unix_us) +
                " us");
  Entries entries(writer);
  Converter converter(entries, geometry);
  using Handler = std::function<bool(const Event&, uint64_t)>;
  auto handler = [&converter]<typename Message>(void (Converter::*method)(uint64_t, const Message&)) -> Handler {
    return [&converter, method](const Event& event, uint64_t t) {
      Message m{};
      if (!decode(event, &m)) return false;
      (converter.*method)(t, m);
      return true;
    };
  };
  const std::map<std::string, Handler> handlers{
      {channels.state, handler(&Converter::state)},
      {channels.setpoint, handler(&Converter::setpoint)},
      {channels.goal, handler(&Converter::goal)},
      {channels.plan_status, handler(&Converter::planStatus)},
      {channels.trajectory, handler(&Converter::trajectory)},
      {channels.daemon_status, handler(&Converter::daemonStatus)},
  };
  converter.setTrajectoryChannel(channels.trajectory);
  for (const Event& event : events) {
    const auto it = handlers.find(event.channel);
    if (it == handlers.end()) {
      ++s.other;
      continue;
    }
    entries.setChannel(event.channel);
    const auto t = static_cast<uint64_t>(event.timestamp_us - events.front().timestamp_us);
    if (it->second(event, t)) {
      ++s.converted;
    } else {
      ++s.undecodable;
    }
  }
  converter.finish();
  if (s.converted == 0) {
    return Result<Conversion, WpilogStatus>::failure(
        WpilogStatus::kNoMessages,
        lcm_path + ": no cyber-planner message in " + std::to_string(s.events) + " events" +
            (s.undecodable > 0 ? " (" + std::to_string(s.undecodable) + " undecodable)" : ""));
  }
  return Conversion{std::move(writer), s};
}

}  // namespace cyber::wpilog

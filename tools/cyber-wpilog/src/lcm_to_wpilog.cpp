#include "cyber/wpilog/lcm_to_wpilog.hpp"

#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

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

// A Mechanism2d ligament: its absolute angle in the side view and its length.
struct Ligament {
  double angle_rad = 0.0;
  double length_m = 0.0;
};

// The segment d, given in a frame turned by direction_rad, as a ligament whose angle stays
// within a quarter turn of direction_rad: a segment pointing backwards is a negative length, so
// that an elevator's ligament keeps the rail's tilt below its zero as above it instead of flipping
// by half a turn.
Ligament ligamentAlong(double direction_rad, const planner::Point2& d) {
  if (d.x() == 0.0) {
    return Ligament{direction_rad + (d.y() == 0.0 ? 0.0 : std::copysign(M_PI / 2, d.y())), std::abs(d.y())};
  }
  return Ligament{direction_rad + std::atan(d.y() / d.x()), std::copysign(d.norm(), d.x())};
}

// Held pieces as one string: the names joined by ',' ("none" for none).
std::string pieceList(const std::vector<std::string>& pieces) {
  std::string out;
  for (const auto& piece : pieces) out += (out.empty() ? "" : ",") + piece;
  return out.empty() ? "none" : out;
}

class Converter {
 public:
  Converter(Entries& entries, const MechanismGeometry& geometry) : e_(entries), g_(geometry) {
    for (const planner::ChainJoint& joint : geometry.chain) j_.push_back(jointNames(joint));
  }

  // A state or setpoint of another joint count than the config's is of another robot: skipped, as
  // the daemon ignores such a state (docs/lcm.md, "Joints by index").
  void state(uint64_t t, const cyberplanner::arm_state_t& m) {
    if (!ours(m.num_joints)) return;
    for (size_t j = 0; j < j_.size(); ++j) {
      e_.putDouble(key(j_[j], "Measured" + j_[j].position), t, m.position[j]);
      e_.putDouble(key(j_[j], "Measured" + j_[j].velocity), t, m.velocity[j]);
    }
    e_.putString("State/Pieces", t, pieceList(m.pieces));
    mechanism("Measured", t, m.position);
  }

  void setpoint(uint64_t t, const cyberplanner::arm_setpoint_t& m) {
    if (!ours(m.num_joints)) return;
    for (size_t j = 0; j < j_.size(); ++j) joint(j_[j], t, m.position[j], m.velocity[j], m.volts[j], m.sequence[j]);
    e_.putString("Setpoint/Mode", t, lcmtypes::modeName(m.mode));
    e_.putInt64("Setpoint/RequestId", t, m.request_id);
    e_.putDouble("Setpoint/TrajectoryTimeSeconds", t, m.trajectory_t_s);
    mechanism("Setpoint", t, m.position);
  }

  void goal(uint64_t t, const cyberplanner::arm_goal_t& m) {
    e_.putInt64("Goal/RequestId", t, m.request_id);
    // A named goal sends no values (docs/lcm.md, "Named goals"): its name is the target.
    if (!m.pose_name.empty()) e_.putString("Goal/PoseName", t, m.pose_name);
    const bool named_without_values = !m.pose_name.empty() && m.num_joints == 0;
    if (!named_without_values && ours(m.num_joints)) {
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
  [[nodiscard]] int64_t otherJointCount() const { return other_joint_count_; }

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
  bool ours(int num_joints) {
    if (num_joints == static_cast<int>(j_.size())) return true;
    ++other_joint_count_;
    return false;
  }

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

  // The mechanism as AdvantageScope draws logged mechanisms (docs/operations.md, "AdvantageScope"):
  // a Mechanism2d of one ligament per joint, each the child of the one before and named as the
  // robot description names its joint, angles in degrees relative to the parent; and each link
  // frame's robot-frame pose as a 3-D component (x forward, z up; the side view's y is z), one per
  // link in chain order.
  void mechanism(const std::string& which, uint64_t t, const std::vector<double>& position) {
    const int n = g_.chain.size();
    if (n == 0) return;
    planner::JointVector q(n);
    for (int j = 0; j < n; ++j) q[j] = position[static_cast<size_t>(j)];
    const std::string m = "Mechanism2d/" + which + "/";
    std::vector<std::string> ligament;  // "Mechanism2d/Measured/Base/elevator/", ".../elevator/arm/", ...
    std::string path = m + "Base/";
    for (const planner::ChainJoint& joint : g_.chain) ligament.push_back(path += joint.name + "/");
    if (!e_.started(m + ".type")) {
      e_.putString(m + ".type", t, "Mechanism2d");
      e_.putBoolean(m + ".controllable", t, false);
      e_.putDoubles(m + "dims", t, {kMechanismWidthM, kMechanismHeightM});
      e_.putString(m + "backgroundColor", t, "#000020");
      e_.putDouble(m + "Base/x", t, g_.chain[0].origin_m.x() + kMechanismOriginXM);
      e_.putDouble(m + "Base/y", t, g_.chain[0].origin_m.y());
      // The links that carry another joint in blue, the last in the colour of its entry.
      for (int j = 0; j < n; ++j) {
        const bool carries = j + 1 < n;
        const std::string& l = ligament[static_cast<size_t>(j)];
        e_.putString(l + ".type", t, "line");
        e_.putString(l + "color", t, carries ? "#3070FF" : which == "Measured" ? "#FF8020" : "#20FF80");
        e_.putDouble(l + "weight", t, carries ? 8.0 : 6.0);
      }
    }
    // Ligament j runs from where joint j sits in its parent's link to its end in link j's frame
    // (MechanismGeometry): a revolute link's along the link turned by its joint, a prismatic
    // link's along its travel from the travel's zero. Angles are summed along the chain, not
    // wrapped: a ligament turns on as its joint does.
    double link_rad = 0.0;  // the previous link's angle (chain.hpp: a prismatic joint keeps it)
    double parent_rad = 0.0;
    for (int j = 0; j < n; ++j) {
      const planner::ChainJoint& joint = g_.chain[j];
      const planner::Point2& end = g_.ligament_end_m[j];
      Ligament l;
      if (joint.type == planner::JointType::kRevolute) {
        link_rad += joint.axis_rad + q[j];
        l = ligamentAlong(link_rad, end);
      } else {
        // The end in the frame of the travel: the carriage is q along it, and its frame keeps the
        // parent's orientation, axis_rad off the travel.
        const double c = std::cos(joint.axis_rad);
        const double s = std::sin(joint.axis_rad);
        l = ligamentAlong(link_rad + joint.axis_rad,
                          planner::Point2(q[j] + c * end.x() + s * end.y(), -s * end.x() + c * end.y()));
      }
      const std::string& name = ligament[static_cast<size_t>(j)];
      e_.putDouble(name + "angle", t, (l.angle_rad - parent_rad) * kRadToDeg);
      e_.putDouble(name + "length", t, l.length_m);
      parent_rad = l.angle_rad;
    }

    // A rotation by -angle about +y turns +x up toward +z by angle.
    std::vector<Pose3d> poses;
    for (const planner::LinkFrame& frame : planner::linkFrames(g_.chain, q)) {
      const double a = frame.angle_rad();
      poses.push_back(Pose3d{frame.origin_m.x(), 0, frame.origin_m.y(), std::cos(-a / 2), 0, std::sin(-a / 2), 0});
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
    std::array<std::array<double, 3>, planner::kMaxJoints> joints;  // position, velocity, feedforward volts
  };

  Entries& e_;
  const MechanismGeometry& g_;
  std::vector<JointNames> j_;  // one per joint of the chain
  std::vector<PlannedSample> planned_;
  std::string channel_of_trajectories_;
  int64_t other_joint_count_ = 0;
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
  const int n = robot.jointCount();
  planner::PerJoint<double> reach_m(n, 0.0);  // how far each link's outline reaches along its x
  for (const planner::LinkGeometry& link : robot.links) {
    if (link.joint < 0 || link.joint >= n) continue;
    for (const planner::ConvexPolygon& p : link.polygons) {
      for (const planner::Point2& v : p.vertices()) reach_m[link.joint] = std::max(reach_m[link.joint], v.x());
    }
  }
  for (int j = 0; j < n; ++j) {
    g.ligament_end_m.push_back(j + 1 < n ? g.chain[j + 1].origin_m : planner::Point2(reach_m[j], 0.0));
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
  s.other_joint_count = converter.otherJointCount();
  if (s.converted == 0) {
    return Result<Conversion, WpilogStatus>::failure(
        WpilogStatus::kNoMessages,
        lcm_path + ": no cyber-planner message in " + std::to_string(s.events) + " events" +
            (s.undecodable > 0 ? " (" + std::to_string(s.undecodable) + " undecodable)" : ""));
  }
  return Conversion{std::move(writer), s};
}

}  // namespace cyber::wpilog

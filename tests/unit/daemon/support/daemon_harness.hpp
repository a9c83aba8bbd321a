#pragma once
// The daemon's logic wired together on a fake clock: coordinator + streamer + a fake planner whose
// plans take a chosen (fake) time. One step() is one stream period; everything the real threads
// would exchange is passed by hand, in the order the real event loop does.

#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cyber/daemon/goal_coordinator.hpp"
#include "cyber/daemon/streamer.hpp"
#include "fake_trajectory.hpp"
#include "reference_model.hpp"

namespace cyber::daemon::test {

struct RecordingSink final : CoordinatorSink {
  std::vector<StatusUpdate> statuses;
  std::vector<std::pair<std::int64_t, MonoNs>> trajectories;  // request id, start
  std::optional<PlanJob> job;
  MonoNs job_started_ns = kNever;
  const MonoNs* clock = nullptr;
  std::vector<PlanJob> jobs_started;
  std::unique_ptr<Program> program;
  std::vector<std::string> notes;
  std::uint32_t release_generation = 0;

  void publishStatus(const StatusUpdate& update) override { statuses.push_back(update); }
  void publishTrajectory(std::int64_t id, const SharedSetpointSource&, MonoNs start) override {
    trajectories.emplace_back(id, start);
  }
  void startPlanning(const PlanJob& j) override {
    job = j;
    job_started_ns = *clock;
    jobs_started.push_back(j);
  }
  void postProgram(std::unique_ptr<Program> p) override { program = std::move(p); }
  void note(NoteLevel, const std::string& text) override { notes.push_back(text); }
  void setReleaseGeneration(std::uint32_t generation) override { release_generation = generation; }

  // Some note contains `text`.
  [[nodiscard]] bool noted(const std::string& text) const {
    for (const auto& n : notes) {
      if (n.find(text) != std::string::npos) return true;
    }
    return false;
  }

  // Statuses of one request, in order.
  [[nodiscard]] std::vector<GoalStatus> of(std::int64_t id) const {
    std::vector<GoalStatus> out;
    for (const auto& s : statuses) {
      if (s.request_id == id) out.push_back(s.status);
    }
    return out;
  }
  [[nodiscard]] const StatusUpdate* last(std::int64_t id) const {
    const StatusUpdate* found = nullptr;
    for (const auto& s : statuses) {
      if (s.request_id == id) found = &s;
    }
    return found;
  }
};

struct TickRecord {
  MonoNs now = 0;
  bool sent = false;
  JointSetpoints setpoints;
  StreamMode mode = StreamMode::kNoState;
  std::int64_t request_id = -1;
};

class Harness {
 public:
  using PlanFn = std::function<planner::Result<PlannedMotion>(const MotionRequest&)>;

  explicit Harness(bool require_robot_enabled = false, double plan_time_s = 0.002)
      : robot(cyber::test::referenceModel()),
        plan_time_s_(plan_time_s),
        streamer_(HoldModel(robot), streamerSettings(require_robot_enabled)),
        coordinator_(robot, coordinatorSettings(), sink) {
    settings_gate_.require_robot_enabled = require_robot_enabled;
    sink.clock = &now;
    plan = [this](const MotionRequest& request) { return defaultPlan(request); };
  }

  static constexpr MonoNs kPeriod = 5'000'000;  // 200 Hz

  // A plan whose duration grows with the distance; rejects goals in `collision_goals`. A stop
  // brakes at a constant rate over stop_duration_s (the velocity falls linearly to zero).
  planner::Result<PlannedMotion> defaultPlan(const MotionRequest& request) const {
    if (request.kind == MotionKind::kStop) {
      PlannedMotion stop;
      const JointVector rest = request.start + 0.5 * stop_duration_s * request.start_velocity;
      stop.trajectory = makeHermite(request.start, request.start_velocity, rest, stop_duration_s, robot);
      return stop;
    }
    for (const auto& q : collision_goals) {
      if ((q - request.goal).norm() < 1e-9) {
        return planner::Result<PlannedMotion>::failure(planner::PlanStatus::kGoalInCollision,
                                                       "goal is 0.01 m from l2_branch (clearance 0.03 m)");
      }
    }
    PlannedMotion motion;
    const double distance = (request.goal - request.start).norm() + 0.2 * request.start_velocity.norm();
    motion.trajectory = makeHermite(request.start, request.start_velocity, request.goal, 0.3 + 0.5 * distance, robot);
    motion.times_ms.total = plan_time_s_ * 1e3;
    return motion;
  }

  void setPlanTime(double seconds) { plan_time_s_ = seconds; }

  // Measured state: where the last setpoint was (perfect tracking) unless `measured` is given.
  void feedState(std::optional<JointVector> measured = std::nullopt) {
    inputs.state_ns = now;
    inputs.measured_q = measured ? *measured : last_position_;
  }
  void heartbeat(bool watchdog) {
    inputs.heartbeat_ns = now;
    inputs.heartbeat_watchdog = watchdog;
  }
  void broadcastDisable() { inputs.broadcast_disable_ns = now; }

  void goal(std::int64_t id, JointVector q, std::string scene = {}, std::vector<std::string> pieces = {},
            double scene_offset_m = 0.0) {
    rawGoal(request(id, q, std::move(scene), std::move(pieces), scene_offset_m));
  }
  static GoalRequest request(std::int64_t id, JointVector q, std::string scene = {},
                             std::vector<std::string> pieces = {}, double scene_offset_m = 0.0) {
    GoalRequest request;
    request.request_id = id;
    request.position = {q[0], q[1]};
    request.num_pieces = static_cast<int>(pieces.size());
    request.pieces = std::move(pieces);
    request.scene_name = std::move(scene);
    request.scene_offset_m = scene_offset_m;
    return request;
  }
  // As the event loop admits a goal: on the gate with the release as the coordinator last set it.
  void rawGoal(const GoalRequest& request) {
    inputs.release_generation = sink.release_generation;
    coordinator_.onGoal(request, now, evaluateGate(inputs, now, settings_gate_));
  }
  void cancel(std::int64_t id, CancelAction action) { coordinator_.onCancel(CancelRequest{id, action}, now); }

  // One stream period: finished plans first (the worker wakes the loop), then the streamer's tick
  // and its events, then time advances. State and heartbeats are refreshed when asked to.
  void step() {
    if (sink.job && now >= sink.job_started_ns + secondsToNs(plan_time_s_)) {
      PlanJob job = *sink.job;
      sink.job.reset();
      coordinator_.onPlanResult(job.job_id, plan(job.request), plan_time_s_, now);
    }
    Program* offered = sink.program.release();
    inputs.release_generation = sink.release_generation;
    TickOutput out;
    streamer_.tick(now, inputs, offered, stop_requested, out);
    for (int i = 0; i < out.retired_count; ++i) delete out.retired[static_cast<size_t>(i)];
    for (int i = 0; i < out.event_count; ++i) {
      events.push_back(out.events[static_cast<size_t>(i)]);
      coordinator_.onStreamEvent(out.events[static_cast<size_t>(i)], now);
    }
    records.push_back(TickRecord{now, out.send_setpoints, out.setpoints, out.mode, out.request_id});
    if (out.send_setpoints) last_position_ = out.setpoints.position;
    now += kPeriod;
    if (auto_state) feedState();
    if (auto_heartbeat) heartbeat(true);
  }
  void run(double seconds) {
    const MonoNs end = now + secondsToNs(seconds);
    while (now < end) step();
  }
  // Runs until request `id` has a final status (or the time limit passes).
  bool runUntilFinal(std::int64_t id, double limit_s = 10.0) {
    const MonoNs end = now + secondsToNs(limit_s);
    while (now < end) {
      const StatusUpdate* s = sink.last(id);
      if (s && isFinal(s->status)) return true;
      step();
    }
    return false;
  }
  // Waits (steps) until the streamer holds on its own, from a fresh state.
  void start(JointVector at) {
    last_position_ = at;
    feedState(at);
    if (settings_gate_.require_robot_enabled) heartbeat(true);
    step();
  }

  [[nodiscard]] const TickRecord& lastRecord() const { return records.back(); }
  GoalCoordinator& coordinator() { return coordinator_; }
  Streamer& streamer() { return streamer_; }

  const planner::RobotModel& robot;
  MonoNs now = 1'000'000'000;
  RobotInputs inputs;
  RecordingSink sink;
  PlanFn plan;
  std::vector<JointVector> collision_goals;
  std::vector<TickRecord> records;
  std::vector<StreamEvent> events;
  bool stop_requested = false;
  bool auto_state = true;
  bool auto_heartbeat = true;
  double stop_duration_s = 0.2;

 private:
  static StreamerSettings streamerSettings(bool require_robot_enabled) {
    StreamerSettings settings;
    settings.gate.require_robot_enabled = require_robot_enabled;
    return settings;
  }
  static CoordinatorSettings coordinatorSettings() {
    CoordinatorSettings settings;
    settings.stream_period_s = 0.005;
    settings.planning_budget_s = 0.03;
    return settings;
  }

  double plan_time_s_;
  GateSettings settings_gate_;
  Streamer streamer_;
  GoalCoordinator coordinator_;
  JointVector last_position_ = JointVector::Zero(2);
};

}  // namespace cyber::daemon::test

// The assembled daemon (event loop, worker and streamer threads, LCM bridge) on memq:// with a
// fake planner and no CAN socket: goals in through LCM, answers out through LCM.

#include "cyber/daemon/io/daemon_probe.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <pthread.h>
#include <sched.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <future>
#include <mutex>
#include <thread>
#include <vector>

#include "cyber/config/load_config.hpp"
#include "cyberplanner/arm_cancel_t.hpp"
#include "cyberplanner/arm_daemon_status_t.hpp"
#include "cyberplanner/arm_goal_t.hpp"
#include "cyberplanner/arm_plan_status_t.hpp"
#include "cyberplanner/arm_setpoint_t.hpp"
#include "cyberplanner/arm_state_t.hpp"
#include "cyberplanner/arm_trajectory_t.hpp"
#include "fake_trajectory.hpp"
#include "latest_value_peer.hpp"
#include "reference_model.hpp"

namespace cyber::daemon::io {
namespace {

using namespace std::chrono_literals;

class FakePlanning final : public PlanningService {
 public:
  explicit FakePlanning(const planner::RobotModel& robot) : robot_(robot) {}
  planner::Result<PlannedMotion> plan(const MotionRequest& request) const override {
    if (request.goal[1] < 0.05) {
      return planner::Result<PlannedMotion>::failure(planner::PlanStatus::kGoalInCollision, "arm in the floor");
    }
    PlannedMotion motion;
    const double duration_s = duration_s_.load();
    // A stop brakes at a constant rate to rest (the velocity falls linearly over duration_s).
    const JointVector to = request.kind == MotionKind::kStop
                               ? JointVector(request.start + 0.5 * duration_s * request.start_velocity)
                               : request.goal;
    motion.trajectory = test::makeHermite(request.start, request.start_velocity, to, duration_s, robot_);
    motion.times_ms.total = 1.0;
    return motion;
  }
  void setDuration(double seconds) { duration_s_.store(seconds); }

 private:
  const planner::RobotModel& robot_;
  std::atomic<double> duration_s_{0.3};
};

// Collects what the daemon publishes (handlers run on the daemon's loop thread).
struct Listener {
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<cyberplanner::arm_plan_status_t> statuses;
  std::vector<cyberplanner::arm_trajectory_t> trajectories;
  std::vector<cyberplanner::arm_setpoint_t> setpoints;
  std::vector<cyberplanner::arm_daemon_status_t> daemon_statuses;

  template <class M>
  void add(std::vector<M>& to, const M* message) {
    std::lock_guard<std::mutex> lock(mutex);
    to.push_back(*message);
    changed.notify_all();
  }
  void onStatus(const lcm::ReceiveBuffer*, const std::string&, const cyberplanner::arm_plan_status_t* m) {
    add(statuses, m);
  }
  void onTrajectory(const lcm::ReceiveBuffer*, const std::string&, const cyberplanner::arm_trajectory_t* m) {
    add(trajectories, m);
  }
  void onSetpoint(const lcm::ReceiveBuffer*, const std::string&, const cyberplanner::arm_setpoint_t* m) {
    add(setpoints, m);
  }
  void onDaemonStatus(const lcm::ReceiveBuffer*, const std::string&, const cyberplanner::arm_daemon_status_t* m) {
    add(daemon_statuses, m);
  }

  // Waits until `done` holds (checked under the lock) or 5 s pass.
  template <class Pred>
  bool waitFor(Pred done) {
    std::unique_lock<std::mutex> lock(mutex);
    return changed.wait_for(lock, 5s, [&] { return done(); });
  }
  std::vector<std::int8_t> statusesOf(std::int64_t id) {
    std::vector<std::int8_t> out;
    for (const auto& s : statuses) {
      if (s.request_id == id) out.push_back(s.status);
    }
    return out;
  }
  bool finalFor(std::int64_t id) {
    for (const auto& s : statuses) {
      if (s.request_id == id && s.status >= cyberplanner::arm_plan_status_t::STATUS_DONE) return true;
    }
    return false;
  }
};

class DaemonMemq : public ::testing::Test {
 protected:
  // full_rate_echo: setpoint_echo_full_rate with an echo timer too slow to publish in a test.
  explicit DaemonMemq(bool full_rate_echo = false) : planning(cyber::test::referenceModel()) {
    DaemonOptions options;
    options.settings.lcm_url = "memq://";
    options.simulate_can = true;
    options.poses = config::loadEmbeddedDefaultConfig().poses;
    options.settings.setpoint_echo_full_rate = full_rate_echo;
    if (full_rate_echo) options.settings.setpoint_echo_rate_hz = 0.1;
    daemon = std::make_unique<Daemon>(cyber::test::referenceModel(), options, planning, nullptr);
    runner = std::async(std::launch::async, [this] { return daemon->run(); });
    onLoop([this] {
      auto& lcm = DaemonProbe::lcm(*daemon);
      lcm.subscribe("ARM_PLAN_STATUS", &Listener::onStatus, &listener);
      lcm.subscribe("ARM_TRAJECTORY", &Listener::onTrajectory, &listener);
      lcm.subscribe("ARM_SETPOINT", &Listener::onSetpoint, &listener);
      lcm.subscribe("ARM_DAEMON_STATUS", &Listener::onDaemonStatus, &listener);
    });
    state_feeder = std::thread([this] {
      while (!stop_feeding) {
        cyberplanner::arm_state_t state{};
        state.num_joints = 2;
        state.position = {0.1, 1.2};
        state.velocity = {0.0, 0.0};
        publish("ARM_STATE", state);
        std::this_thread::sleep_for(20ms);
      }
    });
  }

  ~DaemonMemq() override {
    stop_feeding = true;
    state_feeder.join();
    if (runner.valid()) {
      daemon->requestStop();
      runner.get();
    }
  }

  // Runs `task` on the daemon's loop thread and waits for it. After a stop the loop runs no more
  // tasks; the promise is shared so a task left behind never touches a dead stack frame.
  void onLoop(std::function<void()> task) {
    auto done = std::make_shared<std::promise<void>>();
    auto future = done->get_future();
    DaemonProbe::post(*daemon, [task = std::move(task), done] {
      task();
      done->set_value();
    });
    future.wait_for(2s);
  }

  template <class M>
  void publish(const std::string& channel, const M& message) {
    onLoop([&] { DaemonProbe::lcmFor(*daemon, channel).publish(channel, &message); });
  }
  void publishRaw(const std::string& channel, const std::vector<std::uint8_t>& bytes) {
    onLoop([&] {
      DaemonProbe::lcmFor(*daemon, channel).publish(channel, bytes.data(), static_cast<unsigned>(bytes.size()));
    });
  }

  void goal(std::int64_t id, double q0, double q1, std::vector<std::string> pieces = {}) {
    cyberplanner::arm_goal_t message{};
    message.request_id = id;
    message.num_joints = 2;
    message.position = {q0, q1};
    message.num_pieces = static_cast<std::int8_t>(pieces.size());
    message.pieces = std::move(pieces);
    publish("ARM_GOAL", message);
  }

  void waitForHolding() {
    ASSERT_TRUE(listener.waitFor([&] {
      return !listener.daemon_statuses.empty() &&
             listener.daemon_statuses.back().mode == cyberplanner::arm_daemon_status_t::MODE_HOLDING;
    }));
  }

  FakePlanning planning;
  std::unique_ptr<Daemon> daemon;
  Listener listener;
  std::future<int> runner;
  std::atomic<bool> stop_feeding{false};
  std::thread state_feeder;
};

TEST_F(DaemonMemq, AGoalIsAnsweredAcceptedPlanningExecutingDoneWithATrajectoryAndSetpoints) {
  waitForHolding();
  goal(1, 1.0, 2.0);
  ASSERT_TRUE(listener.waitFor([&] { return listener.finalFor(1); }));
  using S = cyberplanner::arm_plan_status_t;
  EXPECT_EQ(listener.statusesOf(1),
            (std::vector<std::int8_t>{S::STATUS_ACCEPTED, S::STATUS_PLANNING, S::STATUS_EXECUTING, S::STATUS_DONE}));
  // The echo settles on a hold of the target (MODE_HOLDING == 1).
  ASSERT_TRUE(listener.waitFor([&] {
    return !listener.setpoints.empty() && listener.setpoints.back().request_id == 1 &&
           listener.setpoints.back().mode == cyberplanner::arm_setpoint_t::MODE_HOLDING;
  }));
  std::lock_guard<std::mutex> lock(listener.mutex);
  ASSERT_EQ(listener.trajectories.size(), 1u);
  const auto& trajectory = listener.trajectories[0];
  EXPECT_EQ(trajectory.request_id, 1);
  EXPECT_NEAR(trajectory.duration_s, 0.3, 1e-12);
  EXPECT_EQ(trajectory.num_samples, 31);
  EXPECT_NEAR(trajectory.position[0].front(), 0.1, 1e-12);
  EXPECT_NEAR(trajectory.position[1].back(), 2.0, 1e-9);
  bool moving_echo = false;
  for (const auto& s : listener.setpoints) {
    moving_echo |= s.request_id == 1 && s.mode == cyberplanner::arm_setpoint_t::MODE_MOVING;
  }
  EXPECT_TRUE(moving_echo);
  EXPECT_NEAR(listener.setpoints.back().position[1], 2.0, 1e-5);
  EXPECT_EQ(listener.setpoints.back().velocity[1], 0.0);
}

class DaemonMemqFullRateEcho : public DaemonMemq {
 protected:
  DaemonMemqFullRateEcho() : DaemonMemq(true) {}
};

// Desktop simulation (docs/roborio.md): ARM_SETPOINT after every stream tick. The 0.1 Hz echo timer
// alone would publish the first one after 10 s, beyond waitFor's 5 s.
TEST_F(DaemonMemqFullRateEcho, ArmSetpointIsPublishedForEveryStreamTick) {
  ASSERT_TRUE(listener.waitFor([&] { return listener.setpoints.size() >= 50; }));
  std::lock_guard<std::mutex> lock(listener.mutex);
  std::size_t consecutive = 0;
  for (std::size_t i = 1; i < listener.setpoints.size(); ++i) {
    const int step = (listener.setpoints[i].sequence[0] - listener.setpoints[i - 1].sequence[0]) & 0xFF;
    EXPECT_NE(step, 0) << "tick echoed twice at message " << i;
    consecutive += step == 1 ? 1 : 0;
  }
  // Each message is a new tick; most follow the previous tick directly (a busy machine may
  // make the loop skip one now and then).
  EXPECT_GT(consecutive, listener.setpoints.size() / 2);
}

TEST_F(DaemonMemq, BadGoalsAreRejectedWithReasons) {
  waitForHolding();
  goal(1, std::nan(""), 1.0);
  goal(2, 5.0, 1.0);
  goal(3, 0.5, 0.01);  // the fake planner says: in collision
  goal(4, 0.5, 1.0, {"coral", "cone"});
  ASSERT_TRUE(listener.waitFor(
      [&] { return listener.finalFor(1) && listener.finalFor(2) && listener.finalFor(3) && listener.finalFor(4); }));
  using S = cyberplanner::arm_plan_status_t;
  std::lock_guard<std::mutex> lock(listener.mutex);
  EXPECT_EQ(listener.statusesOf(1), std::vector<std::int8_t>{S::STATUS_REJECTED});
  EXPECT_EQ(listener.statusesOf(2), std::vector<std::int8_t>{S::STATUS_REJECTED});
  EXPECT_EQ(listener.statusesOf(3),
            (std::vector<std::int8_t>{S::STATUS_ACCEPTED, S::STATUS_PLANNING, S::STATUS_REJECTED}));
  EXPECT_EQ(listener.statusesOf(4), std::vector<std::int8_t>{S::STATUS_REJECTED});
  EXPECT_NE(listener.statuses[0].reason.find("position[0] (elevator) is not finite"), std::string::npos);
  EXPECT_NE(listener.statuses[1].reason.find("outside [0, 2]"), std::string::npos);
  const auto unknown_piece = std::find_if(listener.statuses.begin(), listener.statuses.end(),
                                          [](const auto& status) { return status.request_id == 4; });
  ASSERT_NE(unknown_piece, listener.statuses.end());
  EXPECT_NE(unknown_piece->reason.find("unknown game piece 'cone' in pieces[1] (this robot's: algae, coral)"),
            std::string::npos)
      << unknown_piece->reason;
  // Goal 4 is refused on receipt and goal 3 by the planner's thread: their answers may come in
  // either order.
  const auto in_collision = std::find_if(listener.statuses.rbegin(), listener.statuses.rend(),
                                         [](const auto& status) { return status.request_id == 3; });
  ASSERT_NE(in_collision, listener.statuses.rend());
  EXPECT_EQ(in_collision->reason, "goal in collision: arm in the floor");
}

TEST_F(DaemonMemq, GarbageIsCountedAndTheDaemonKeepsWorking) {
  waitForHolding();
  publishRaw("ARM_GOAL", {1, 2, 3});
  publishRaw("ARM_GOAL", std::vector<std::uint8_t>(64, 0xff));
  cyberplanner::arm_state_t wrong_type{};
  publish("ARM_GOAL", wrong_type);  // fingerprint of another type
  // A goal whose scene-name length field says 2^31 - 1 bytes.
  cyberplanner::arm_goal_t valid{};
  valid.scene_name = "reef";
  std::vector<std::uint8_t> bytes(static_cast<size_t>(valid.getEncodedSize()));
  valid.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  const size_t length_at = bytes.size() - 8 - 4 - 5;  // int32 length, "reef\0", then scene_offset_m
  bytes[length_at] = 0x7f;
  bytes[length_at + 1] = bytes[length_at + 2] = bytes[length_at + 3] = 0xff;
  publishRaw("ARM_GOAL", bytes);
  cyberplanner::arm_state_t nan_state{};
  nan_state.num_joints = 2;
  nan_state.position = {std::nan(""), 1.0};
  nan_state.velocity = {0.0, 0.0};
  publish("ARM_STATE", nan_state);
  // A state of three joints: not this robot's.
  cyberplanner::arm_state_t three{};
  three.num_joints = 3;
  three.position = {0.1, 1.2, 0.0};
  three.velocity = {0.0, 0.0, 0.0};
  publish("ARM_STATE", three);
  // A goal whose num_pieces is negative: lcm-gen would throw sizing the array; undecodable.
  cyberplanner::arm_goal_t no_pieces{};
  std::vector<std::uint8_t> negative(static_cast<size_t>(no_pieces.getEncodedSize()));
  no_pieces.encode(negative.data(), 0, static_cast<int>(negative.size()));
  // fingerprint, utime, request_id, pose_name "" (length 1, NUL), num_joints 0, then num_pieces
  negative[8 + 2 * 8 + 5 + 1] = 0xff;
  publishRaw("ARM_GOAL", negative);
  // And one whose num_joints is negative.
  std::vector<std::uint8_t> no_joints = negative;
  no_joints[8 + 2 * 8 + 5 + 1] = 0;
  no_joints[8 + 2 * 8 + 5] = 0xff;
  publishRaw("ARM_GOAL", no_joints);
  ASSERT_TRUE(listener.waitFor(
      [&] { return !listener.daemon_statuses.empty() && listener.daemon_statuses.back().decode_errors >= 8; }));
  goal(7, 1.0, 1.0);
  ASSERT_TRUE(listener.waitFor([&] { return listener.finalFor(7); }));
  std::lock_guard<std::mutex> lock(listener.mutex);
  EXPECT_EQ(listener.statuses.back().status, cyberplanner::arm_plan_status_t::STATUS_DONE);
}

// Whether this process may use SCHED_FIFO (root, CAP_SYS_NICE, RLIMIT_RTPRIO), tried on a thread.
bool realtimeAllowed() {
  bool allowed = false;
  std::thread probe([&] {
    sched_param param{};
    param.sched_priority = 50;
    allowed = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0;
  });
  probe.join();
  return allowed;
}

TEST_F(DaemonMemq, StatusSaysWhetherTheStreamerGotRealTimePriority) {
  waitForHolding();
  ASSERT_TRUE(listener.waitFor([&] { return !listener.daemon_statuses.empty(); }));
  std::lock_guard<std::mutex> lock(listener.mutex);
  EXPECT_EQ(listener.daemon_statuses.back().realtime_priority, realtimeAllowed() ? 50 : 0);
}

// Peers learn what joint 0 and joint 1 are from the daemon itself (docs/lcm.md).
TEST_F(DaemonMemq, StatusNamesTheJointsAndTheirUnits) {
  ASSERT_TRUE(listener.waitFor([&] { return !listener.daemon_statuses.empty(); }));
  std::lock_guard<std::mutex> lock(listener.mutex);
  const auto& status = listener.daemon_statuses.back();
  EXPECT_EQ(status.num_joints, 2);
  EXPECT_EQ(status.joint_names, (std::vector<std::string>{"elevator", "arm"}));
  EXPECT_EQ(status.joint_units, (std::vector<std::string>{"m", "rad"}));
}

// ARM_GOAL's pose_name is resolved with the daemon's configuration: [poses.none] STOW =
// [0.20, 1.57] of config/reefscape-2025.toml (docs/lcm.md, "Named goals").
TEST_F(DaemonMemq, ANamedGoalMovesToThePoseOfItsHeldSet) {
  waitForHolding();
  cyberplanner::arm_goal_t message{};
  message.request_id = 11;
  message.pose_name = "STOW";  // num_joints 0: no values needed
  publish("ARM_GOAL", message);
  ASSERT_TRUE(listener.waitFor([&] { return listener.finalFor(11); }));
  std::lock_guard<std::mutex> lock(listener.mutex);
  EXPECT_EQ(listener.statuses.back().status, cyberplanner::arm_plan_status_t::STATUS_DONE)
      << listener.statuses.back().reason;
  ASSERT_FALSE(listener.trajectories.empty());
  EXPECT_EQ(listener.trajectories.back().num_joints, 2);
  EXPECT_NEAR(listener.trajectories.back().position[0].back(), 0.20, 1e-9);
  EXPECT_NEAR(listener.trajectories.back().position[1].back(), 1.57, 1e-9);
}

TEST_F(DaemonMemq, AnUnknownNameOrAnotherJointCountIsRejectedWithTheReason) {
  waitForHolding();
  cyberplanner::arm_goal_t unknown{};
  unknown.request_id = 12;
  unknown.pose_name = "HOLD_HIGH";
  unknown.num_pieces = 1;
  unknown.pieces = {"coral"};
  publish("ARM_GOAL", unknown);
  cyberplanner::arm_goal_t three{};
  three.request_id = 13;
  three.num_joints = 3;
  three.position = {0.5, 1.0, 0.0};
  publish("ARM_GOAL", three);
  ASSERT_TRUE(listener.waitFor([&] { return listener.finalFor(12) && listener.finalFor(13); }));
  std::lock_guard<std::mutex> lock(listener.mutex);
  using S = cyberplanner::arm_plan_status_t;
  EXPECT_EQ(listener.statusesOf(12), std::vector<std::int8_t>{S::STATUS_REJECTED});
  EXPECT_EQ(listener.statusesOf(13), std::vector<std::int8_t>{S::STATUS_REJECTED});
  EXPECT_EQ(listener.statuses[0].reason,
            "invalid input: no pose \"HOLD_HIGH\" for the held set \"coral\" (its poses: STOW, INTAKE, L1, L2, L3, "
            "L4, NET); it is a pose of \"algae\"");
  EXPECT_EQ(listener.statuses[1].reason, "invalid input: num_joints = 3 but this robot has 2 joints (elevator, arm)");
}

// ARM_STATE is taken and stamped on the state receiver's thread, not on the event loop: a state
// that arrives while the loop is busy (here: blocked) reaches the streamer at once, so the loop's
// own scheduling never counts as the state's age (docs/design.md, "Threads and ownership").
TEST_F(DaemonMemq, AStateIsTakenWhileTheEventLoopIsBusy) {
  waitForHolding();
  auto blocked = std::make_shared<std::promise<void>>();
  auto release = std::make_shared<std::promise<void>>();
  std::future<void> loop_blocked = blocked->get_future();
  std::shared_future<void> released = release->get_future().share();
  DaemonProbe::post(*daemon, [blocked, released] {
    blocked->set_value();
    released.wait_for(5s);
  });
  loop_blocked.wait();
  cyberplanner::arm_state_t state{};
  state.num_joints = 2;
  state.position = {0.3, 1.3};
  state.velocity = {0.0, 0.0};
  // From this thread: the loop is blocked, and memq:// publishing is thread-safe (LCM locks it).
  DaemonProbe::lcmFor(*daemon, "ARM_STATE").publish("ARM_STATE", &state);
  bool taken = false;
  for (int i = 0; i < 400 && !taken; ++i) {
    taken = DaemonProbe::channels(*daemon).state.load().measured_q[0] == state.position[0];
    if (!taken) std::this_thread::sleep_for(5ms);
  }
  release->set_value();
  EXPECT_TRUE(taken) << "the state waited for the event loop";
}

// The streamer never waits for the state receiver: with a store left unfinished (on one CPU, the
// receiver preempted by the streamer in the middle of it) the streamer keeps ticking.
TEST_F(DaemonMemq, TheStreamerKeepsTickingWhileAStateStoreIsUnfinished) {
  waitForHolding();
  StreamerChannels& channels = DaemonProbe::channels(*daemon);
  LatestValueTestPeer<MeasuredStateData>::beginStore(channels.state);
  const std::int64_t before = channels.snapshot.load().ticks;
  bool ticking = false;
  for (int i = 0; i < 400 && !ticking; ++i) {
    ticking = channels.snapshot.load().ticks >= before + 10;
    if (!ticking) std::this_thread::sleep_for(5ms);
  }
  LatestValueTestPeer<MeasuredStateData>::endStore(channels.state);
  EXPECT_TRUE(ticking) << "the streamer waited for an unfinished ARM_STATE store";
}

// ARM_CANCEL through LCM (docs/lcm.md, "Cancel and manual override").
class DaemonMemqCancel : public DaemonMemq {
 protected:
  void cancel(std::int64_t id, std::int8_t action) {
    cyberplanner::arm_cancel_t message{};
    message.request_id = id;
    message.action = action;
    publish("ARM_CANCEL", message);
  }
  bool seen(std::int64_t id, std::int8_t status) {
    for (const auto& s : listener.statuses) {
      if (s.request_id == id && s.status == status) return true;
    }
    return false;
  }
  std::string finalReason(std::int64_t id) {
    std::lock_guard<std::mutex> lock(listener.mutex);
    for (const auto& s : listener.statuses) {
      if (s.request_id == id && s.status >= cyberplanner::arm_plan_status_t::STATUS_DONE) return s.reason;
    }
    return "";
  }
};

TEST_F(DaemonMemqCancel, AHoldCancelsTheGoalAndBrakesToRest) {
  using S = cyberplanner::arm_plan_status_t;
  using M = cyberplanner::arm_setpoint_t;
  waitForHolding();
  planning.setDuration(3.0);
  goal(1, 1.8, 3.0);
  ASSERT_TRUE(listener.waitFor([&] { return seen(1, S::STATUS_EXECUTING); }));
  std::this_thread::sleep_for(300ms);
  planning.setDuration(1.0);  // the stop brakes over 1 s
  cancel(1, cyberplanner::arm_cancel_t::ACTION_HOLD);
  ASSERT_TRUE(listener.waitFor([&] { return listener.finalFor(1); }));
  EXPECT_EQ(listener.statusesOf(1), (std::vector<std::int8_t>{S::STATUS_ACCEPTED, S::STATUS_PLANNING,
                                                              S::STATUS_EXECUTING, S::STATUS_CANCELLED}));
  EXPECT_EQ(finalReason(1), "cancelled by ARM_CANCEL: hold");
  // The stop is streamed under request 1, then held at rest, well short of the target (1.8, 3.0).
  ASSERT_TRUE(
      listener.waitFor([&] { return listener.trajectories.size() == 2 && listener.trajectories[1].request_id == 1; }));
  ASSERT_TRUE(listener.waitFor([&] {
    return !listener.setpoints.empty() && listener.setpoints.back().mode == M::MODE_HOLDING &&
           listener.setpoints.back().request_id == 1;
  }));
  std::lock_guard<std::mutex> lock(listener.mutex);
  EXPECT_EQ(listener.setpoints.back().velocity[0], 0.0);
  EXPECT_EQ(listener.setpoints.back().velocity[1], 0.0);
  EXPECT_LT(listener.setpoints.back().position[1], 2.5);
  EXPECT_EQ(listener.statusesOf(1).size(), 4u);  // no DONE for the cancelled goal
}

TEST_F(DaemonMemqCancel, AReleaseStopsTheSetpointsWithModeReleasedUntilTheNextGoal) {
  using S = cyberplanner::arm_plan_status_t;
  using D = cyberplanner::arm_daemon_status_t;
  waitForHolding();
  planning.setDuration(3.0);
  goal(2, 1.8, 3.0);
  ASSERT_TRUE(listener.waitFor([&] { return seen(2, S::STATUS_EXECUTING); }));
  cancel(-1, cyberplanner::arm_cancel_t::ACTION_RELEASE);
  ASSERT_TRUE(listener.waitFor([&] { return listener.finalFor(2); }));
  EXPECT_EQ(finalReason(2), "cancelled by ARM_CANCEL: release (manual override)");
  ASSERT_TRUE(listener.waitFor(
      [&] { return !listener.daemon_statuses.empty() && listener.daemon_statuses.back().mode == D::MODE_RELEASED; }));
  // No ARM_SETPOINT while released (the echo copies the CAN setpoints, and none are sent).
  std::size_t echoes = 0;
  {
    std::lock_guard<std::mutex> lock(listener.mutex);
    echoes = listener.setpoints.size();
    EXPECT_FALSE(listener.daemon_statuses.back().motion_allowed);
  }
  std::this_thread::sleep_for(300ms);
  {
    std::lock_guard<std::mutex> lock(listener.mutex);
    EXPECT_EQ(listener.setpoints.size(), echoes);
    EXPECT_EQ(listener.daemon_statuses.back().mode, D::MODE_RELEASED);
  }
  // The next goal ends the release; it starts from the measured state (0.1, 1.2: the feeder's).
  planning.setDuration(0.3);
  goal(3, 1.0, 2.0);
  ASSERT_TRUE(listener.waitFor([&] { return listener.finalFor(3); }));
  EXPECT_EQ(listener.statusesOf(3),
            (std::vector<std::int8_t>{S::STATUS_ACCEPTED, S::STATUS_PLANNING, S::STATUS_EXECUTING, S::STATUS_DONE}));
  std::lock_guard<std::mutex> lock(listener.mutex);
  ASSERT_FALSE(listener.trajectories.empty());
  EXPECT_EQ(listener.trajectories.back().request_id, 3);
  EXPECT_NEAR(listener.trajectories.back().position[0].front(), 0.1, 1e-12);
  EXPECT_NEAR(listener.trajectories.back().position[1].front(), 1.2, 1e-12);
}

TEST_F(DaemonMemqCancel, UndecodableCancelsAreCounted) {
  waitForHolding();
  publishRaw("ARM_CANCEL", {1, 2, 3});
  cancel(5, 7);  // no such action
  ASSERT_TRUE(listener.waitFor(
      [&] { return !listener.daemon_statuses.empty() && listener.daemon_statuses.back().decode_errors >= 2; }));
  std::lock_guard<std::mutex> lock(listener.mutex);
  EXPECT_EQ(listener.daemon_statuses.back().mode, cyberplanner::arm_daemon_status_t::MODE_HOLDING);
}

TEST_F(DaemonMemq, StopHoldsCancelsOpenGoalsAndReturnsZero) {
  waitForHolding();
  cyberplanner::arm_goal_t message{};
  message.request_id = 5;
  message.num_joints = 2;
  message.position = {1.8, 3.0};
  publish("ARM_GOAL", message);
  ASSERT_TRUE(listener.waitFor([&] {
    for (const auto& s : listener.statuses) {
      if (s.request_id == 5 && s.status == cyberplanner::arm_plan_status_t::STATUS_EXECUTING) return true;
    }
    return false;
  }));
  daemon->requestStop();
  EXPECT_EQ(runner.get(), 0);
  std::lock_guard<std::mutex> lock(listener.mutex);
  EXPECT_EQ(listener.statuses.back().request_id, 5);
  EXPECT_EQ(listener.statuses.back().status, cyberplanner::arm_plan_status_t::STATUS_CANCELLED);
  EXPECT_EQ(listener.statuses.back().reason, "daemon shutting down");
}

}  // namespace
}  // namespace cyber::daemon::io

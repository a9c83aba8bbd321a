#include "cyber/daemon/robot_link.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <vector>

#include "cyber/can/robot_frames.hpp"

namespace cyber::daemon {
namespace {

constexpr MonoNs kMs = 1'000'000;

// Hands out its frames in order, then EAGAIN (or `final_error` once, e.g. ENETDOWN).
class QueueSource final : public RobotFrameSource {
 public:
  std::vector<can::Frame> frames;
  size_t next = 0;
  int reads = 0;
  int final_error = EAGAIN;

  can::IoResult read(can::Frame& frame) override {
    ++reads;
    if (next >= frames.size()) return can::ioResultFromErrno(final_error);
    frame = frames[next++];
    return {};
  }
};

can::Frame heartbeat(bool watchdog) {
  can::Heartbeat h;
  h.enabled = watchdog;
  h.system_watchdog = watchdog;
  return can::encodeHeartbeat(h);
}

can::Frame standardIdZero() {
  can::Frame f;
  f.id = 0;
  f.extended = false;
  f.dlc = 2;
  return f;
}

TEST(RobotLink, HeartbeatsAndDisablesAreTakenInAtTheTick) {
  QueueSource source;
  source.frames = {heartbeat(true), can::makeBroadcastDisable(), standardIdZero(), heartbeat(false), heartbeat(true)};
  RobotLink link;
  EXPECT_EQ(drainRobotFrames(source, 50 * kMs, link), 5);
  EXPECT_EQ(link.heartbeat_ns, 50 * kMs);
  EXPECT_TRUE(link.heartbeat_watchdog);  // the latest heartbeat's bit
  EXPECT_EQ(link.broadcast_disable_ns, 50 * kMs);
  EXPECT_EQ(link.broadcast_disable_count, 2u);  // both forms of id 0
  // Nothing new: nothing changes.
  EXPECT_EQ(drainRobotFrames(source, 55 * kMs, link), 0);
  EXPECT_EQ(link.heartbeat_ns, 50 * kMs);
  source.frames.push_back(heartbeat(false));
  EXPECT_EQ(drainRobotFrames(source, 60 * kMs, link), 1);
  EXPECT_EQ(link.heartbeat_ns, 60 * kMs);
  EXPECT_FALSE(link.heartbeat_watchdog);
}

// The link reads heartbeats in the configured controller's layout (docs/can-protocol.md, "Robot
// heartbeat"): the bit that is Systemcore's FTC motor override is a replay-number bit on a roboRIO.
TEST(RobotLink, TheConfiguredLayoutDecidesWhatTheOverrideBitMeans) {
  can::Heartbeat h;
  h.enabled = true;
  h.system_watchdog = true;
  h.ftc_motor_override = true;
  const can::Frame frame = can::encodeHeartbeat(h, can::HeartbeatLayout::kSystemcore);
  ASSERT_EQ(frame.data[5], 0x80);
  GateSettings settings;
  settings.require_robot_enabled = true;

  RobotLink systemcore;  // the default: Systemcore's reading
  EXPECT_EQ(systemcore.heartbeat_layout, can::HeartbeatLayout::kSystemcore);
  QueueSource source;
  source.frames = {frame};
  EXPECT_EQ(drainRobotFrames(source, 10 * kMs, systemcore), 1);
  EXPECT_TRUE(systemcore.heartbeat_watchdog);
  EXPECT_TRUE(systemcore.heartbeat_motor_override);
  RobotInputs inputs;
  inputs.state_ns = 10 * kMs;
  applyRobotLink(systemcore, inputs);
  EXPECT_EQ(evaluateGate(inputs, 10 * kMs, settings).reason, GateReason::kMotorOverride);

  RobotLink roborio;
  roborio.heartbeat_layout = can::HeartbeatLayout::kRoboRio;  // replay number 32: no override
  source.frames.push_back(frame);
  EXPECT_EQ(drainRobotFrames(source, 10 * kMs, roborio), 1);
  EXPECT_TRUE(roborio.heartbeat_watchdog);
  EXPECT_FALSE(roborio.heartbeat_motor_override);
  applyRobotLink(roborio, inputs);
  EXPECT_TRUE(evaluateGate(inputs, 10 * kMs, settings).open());
}

TEST(RobotLink, MalformedHeartbeatsAndOtherFramesChangeNothing) {
  QueueSource source;
  can::Frame short_heartbeat = heartbeat(true);
  short_heartbeat.dlc = 3;
  for (int i = 3; i < 8; ++i) short_heartbeat.data[static_cast<size_t>(i)] = 0;
  can::Frame remote = heartbeat(true);
  remote.remote = true;
  remote.data = {};
  can::Frame other = heartbeat(true);
  other.id = 0x123;
  other.extended = false;
  can::Frame bus_error;
  bus_error.error = true;
  bus_error.id = 0x40;
  source.frames = {short_heartbeat, remote, other, bus_error};
  RobotLink link;
  EXPECT_EQ(drainRobotFrames(source, 10 * kMs, link), 4);
  EXPECT_EQ(link.heartbeat_ns, kNever);
  EXPECT_FALSE(link.heartbeat_watchdog);
  EXPECT_EQ(link.broadcast_disable_count, 0u);
  EXPECT_EQ(link.bad_heartbeats, 2);  // the short one and the remote one; the others are not heartbeats
}

TEST(RobotLink, AFloodIsReadInBoundedSlicesAndAReadErrorEndsTheDrain) {
  QueueSource source;
  source.frames.assign(100, heartbeat(true));
  RobotLink link;
  EXPECT_EQ(drainRobotFrames(source, kMs, link, 32), 32);
  EXPECT_EQ(source.reads, 32);
  EXPECT_EQ(drainRobotFrames(source, 2 * kMs, link, 32), 32);
  EXPECT_EQ(drainRobotFrames(source, 3 * kMs, link, 32), 32);
  EXPECT_EQ(drainRobotFrames(source, 4 * kMs, link, 32), 4);
  QueueSource down;
  down.final_error = ENETDOWN;
  EXPECT_EQ(drainRobotFrames(down, 5 * kMs, link), 0);
  EXPECT_EQ(down.reads, 1);
  EXPECT_EQ(link.heartbeat_ns, 4 * kMs);
}

// The event loop stamps a heartbeat when it reads it; when it reads late, that stamp is newer than
// the streamer's, which is at most one tick after the arrival. Only the streamer's reading counts.
TEST(RobotLink, TheStreamersReadingReplacesTheEventLoopsEvenWhenTheLoopsLooksNewer) {
  RobotInputs inputs;
  inputs.state_ns = 90 * kMs;
  inputs.heartbeat_ns = 125 * kMs;  // the loop took in the 0 ms heartbeat 125 ms late
  inputs.heartbeat_watchdog = true;
  inputs.broadcast_disable_ns = 80 * kMs;
  inputs.broadcast_disable_count = 1;  // the event loop saw the same disable the link did
  RobotLink link;
  link.heartbeat_ns = 5 * kMs;
  link.heartbeat_watchdog = true;
  link.broadcast_disable_ns = 82 * kMs;
  link.broadcast_disable_count = 1;
  RobotInputs applied = inputs;
  applyRobotLink(link, applied);
  EXPECT_EQ(applied.heartbeat_ns, 5 * kMs);
  EXPECT_EQ(applied.broadcast_disable_ns, 82 * kMs);
  EXPECT_EQ(applied.broadcast_disable_count, 1u);  // not 2: one disable on the bus
  EXPECT_EQ(applied.state_ns, 90 * kMs);           // the rest is the event loop's
  GateSettings settings;
  EXPECT_EQ(evaluateGate(applied, 110 * kMs, settings).reason, GateReason::kNoHeartbeat);
  EXPECT_TRUE(evaluateGate(inputs, 110 * kMs, settings).reason != GateReason::kNoHeartbeat);

  RobotLink empty;  // nothing on the bus yet: no heartbeat, whatever the loop says
  applied = inputs;
  applyRobotLink(empty, applied);
  EXPECT_EQ(applied.heartbeat_ns, kNever);
  EXPECT_FALSE(applied.heartbeat_watchdog);
  EXPECT_EQ(applied.broadcast_disable_count, 0u);
}

// The gate a late event loop would close stays open on the streamer's own reading, and the
// heartbeat timeout still applies to it.
TEST(RobotLink, TheGateUsesTheStreamersReadingWhenTheEventLoopIsLate) {
  GateSettings settings;
  settings.require_robot_enabled = true;
  RobotInputs inputs;
  inputs.state_ns = 500 * kMs;
  inputs.heartbeat_ns = 380 * kMs;  // the loop last took one in 120 ms ago
  inputs.heartbeat_watchdog = true;
  ASSERT_EQ(evaluateGate(inputs, 500 * kMs, settings).reason, GateReason::kNoHeartbeat);
  QueueSource source;
  source.frames = {heartbeat(true)};
  RobotLink link;
  drainRobotFrames(source, 495 * kMs, link);
  applyRobotLink(link, inputs);
  EXPECT_TRUE(evaluateGate(inputs, 500 * kMs, settings).open());
  EXPECT_EQ(evaluateGate(inputs, 595 * kMs, settings).reason, GateReason::kNoHeartbeat);
}

}  // namespace
}  // namespace cyber::daemon

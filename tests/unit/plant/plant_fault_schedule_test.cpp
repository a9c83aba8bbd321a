// Fault specs of cyber-plant-sim's --fault and the schedule that fires them.

#include <gtest/gtest.h>

#include "cyber/plant/fault_schedule.hpp"

namespace cyber::plant {
namespace {

TEST(FaultSchedule, ParsesEveryKindBothWays) {
  for (auto kind : {FaultKind::kHeartbeatStop, FaultKind::kHeartbeatResume, FaultKind::kHeartbeatDisabled,
                    FaultKind::kHeartbeatEnabled, FaultKind::kBroadcastDisable, FaultKind::kSilent,
                    FaultKind::kStateResume, FaultKind::kExit}) {
    const std::string name(toString(kind));
    EXPECT_EQ(parseFaultKind(name), kind) << name;
    const auto parsed = parseFault(name + "@2.5");
    ASSERT_TRUE(parsed.event) << parsed.error;
    EXPECT_EQ(*parsed.event, (FaultEvent{kind, FaultAnchor::kStart, 2.5}));
    const auto relative = parseFault(name + "@motion+0.25");
    ASSERT_TRUE(relative.event) << relative.error;
    EXPECT_EQ(*relative.event, (FaultEvent{kind, FaultAnchor::kMotion, 0.25}));
  }
  EXPECT_EQ(toString(FaultKind::kBroadcastDisable), "disable");
  EXPECT_EQ(toString(FaultKind::kSilent), "silent");
}

TEST(FaultSchedule, RejectsBadSpecsWithAReason) {
  for (const char* bad : {"heartbeat-stop", "heartbeat-stop@", "@1", "nonsense@1", "silent@-1",
                          "silent@motion-1", "silent@motion+", "silent@1s", "silent@nan", "silent@inf",
                          "silent@+1", "silent@ 1", "Silent@1", "silent@1@2"}) {
    const auto parsed = parseFault(bad);
    EXPECT_FALSE(parsed.event) << bad;
    EXPECT_FALSE(parsed.error.empty()) << bad;
  }
  EXPECT_NE(parseFault("nonsense@1").error.find("heartbeat-stop"), std::string::npos);  // lists kinds
}

TEST(FaultSchedule, SwitchesFollowTheFaults) {
  OutputSwitches s;
  EXPECT_EQ(s, (OutputSwitches{true, true, true, false}));
  s = applyFault(s, FaultKind::kHeartbeatStop);
  EXPECT_FALSE(s.heartbeat);
  s = applyFault(s, FaultKind::kHeartbeatDisabled);
  EXPECT_FALSE(s.heartbeat_enabled);
  s = applyFault(s, FaultKind::kHeartbeatResume);
  EXPECT_TRUE(s.heartbeat);
  EXPECT_FALSE(s.heartbeat_enabled);
  s = applyFault(s, FaultKind::kHeartbeatEnabled);
  EXPECT_TRUE(s.heartbeat_enabled);
  s = applyFault(s, FaultKind::kSilent);
  EXPECT_FALSE(s.publish_state);
  EXPECT_EQ(applyFault(s, FaultKind::kBroadcastDisable), s);
  s = applyFault(s, FaultKind::kStateResume);
  EXPECT_TRUE(s.publish_state);
  EXPECT_FALSE(s.exit);
  EXPECT_TRUE(applyFault(s, FaultKind::kExit).exit);
}

TEST(FaultSchedule, FiresInTimeOrderWithTiesInCommandLineOrder) {
  FaultSchedule schedule({{FaultKind::kHeartbeatResume, FaultAnchor::kStart, 3.0},
                          {FaultKind::kHeartbeatStop, FaultAnchor::kStart, 2.0},
                          {FaultKind::kSilent, FaultAnchor::kStart, 3.0},
                          {FaultKind::kExit, FaultAnchor::kStart, 9.0}});
  EXPECT_EQ(schedule.nextDue_s(), 2.0);
  EXPECT_TRUE(schedule.takeDue(1.999).empty());
  EXPECT_EQ(schedule.takeDue(2.0), std::vector<FaultKind>{FaultKind::kHeartbeatStop});
  EXPECT_EQ(schedule.nextDue_s(), 3.0);
  EXPECT_EQ(schedule.takeDue(5.0), (std::vector<FaultKind>{FaultKind::kHeartbeatResume, FaultKind::kSilent}));
  EXPECT_EQ(schedule.pending(), 1u);
  EXPECT_EQ(schedule.takeDue(10.0), std::vector<FaultKind>{FaultKind::kExit});
  EXPECT_FALSE(schedule.nextDue_s());
}

TEST(FaultSchedule, MotionEventsWaitForTheFirstMotion) {
  FaultSchedule schedule({{FaultKind::kHeartbeatStop, FaultAnchor::kMotion, 0.3},
                          {FaultKind::kExit, FaultAnchor::kStart, 10.0}});
  EXPECT_EQ(schedule.nextDue_s(), 10.0);
  EXPECT_TRUE(schedule.takeDue(5.0).empty());
  EXPECT_FALSE(schedule.motionAnchored());
  schedule.motionSeen(4.0);
  EXPECT_TRUE(schedule.motionAnchored());
  schedule.motionSeen(6.0);  // only the first motion counts
  EXPECT_DOUBLE_EQ(*schedule.nextDue_s(), 4.3);
  EXPECT_TRUE(schedule.takeDue(4.29).empty());
  EXPECT_EQ(schedule.takeDue(4.31), std::vector<FaultKind>{FaultKind::kHeartbeatStop});
}

}  // namespace
}  // namespace cyber::plant

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
    EXPECT_EQ(*parsed.event, (FaultEvent{kind, 0, 2.5}));
    const auto relative = parseFault(name + "@motion+0.25");
    ASSERT_TRUE(relative.event) << relative.error;
    EXPECT_EQ(*relative.event, (FaultEvent{kind, 1, 0.25}));
    const auto third = parseFault(name + "@motion3+0");
    ASSERT_TRUE(third.event) << third.error;
    EXPECT_EQ(*third.event, (FaultEvent{kind, 3, 0.0}));
  }
  EXPECT_EQ(toString(FaultKind::kBroadcastDisable), "disable");
  EXPECT_EQ(toString(FaultKind::kSilent), "silent");
}

TEST(FaultSchedule, RejectsBadSpecsWithAReason) {
  for (const char* bad : {"heartbeat-stop",
                          "heartbeat-stop@",
                          "@1",
                          "nonsense@1",
                          "silent@-1",
                          "silent@motion-1",
                          "silent@motion+",
                          "silent@1s",
                          "silent@nan",
                          "silent@inf",
                          "silent@+1",
                          "silent@ 1",
                          "Silent@1",
                          "silent@1@2",
                          "silent@motion0+1",
                          "silent@motion1000+1",
                          "silent@motionx+1",
                          "silent@motion 2+1",
                          "silent@motion",
                          "silent@motion2",
                          "silent@motion-2+1",
                          "silent@motion99999999999+1"}) {
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
  FaultSchedule schedule({{FaultKind::kHeartbeatResume, 0, 3.0},
                          {FaultKind::kHeartbeatStop, 0, 2.0},
                          {FaultKind::kSilent, 0, 3.0},
                          {FaultKind::kExit, 0, 9.0}});
  EXPECT_EQ(schedule.nextDue_s(), 2.0);
  EXPECT_TRUE(schedule.takeDue(1.999).empty());
  EXPECT_EQ(schedule.takeDue(2.0), std::vector<FaultKind>{FaultKind::kHeartbeatStop});
  EXPECT_EQ(schedule.nextDue_s(), 3.0);
  EXPECT_EQ(schedule.takeDue(5.0), (std::vector<FaultKind>{FaultKind::kHeartbeatResume, FaultKind::kSilent}));
  EXPECT_EQ(schedule.pending(), 1u);
  EXPECT_EQ(schedule.takeDue(10.0), std::vector<FaultKind>{FaultKind::kExit});
  EXPECT_FALSE(schedule.nextDue_s());
}

TEST(FaultSchedule, MotionEventsWaitForTheirMotion) {
  FaultSchedule schedule(
      {{FaultKind::kHeartbeatStop, 1, 0.3}, {FaultKind::kBroadcastDisable, 2, 0.1}, {FaultKind::kExit, 0, 10.0}});
  EXPECT_EQ(schedule.nextDue_s(), 10.0);
  EXPECT_TRUE(schedule.takeDue(5.0).empty());
  schedule.motionStarted(1, 4.0);
  schedule.motionStarted(1, 6.0);  // a motion keeps its first start
  EXPECT_DOUBLE_EQ(*schedule.nextDue_s(), 4.3);
  EXPECT_TRUE(schedule.takeDue(4.29).empty());
  EXPECT_EQ(schedule.takeDue(4.31), std::vector<FaultKind>{FaultKind::kHeartbeatStop});
  EXPECT_EQ(schedule.nextDue_s(), 10.0);  // motion 2 not yet
  schedule.motionStarted(0, 1.0);         // not a motion number: ignored
  schedule.motionStarted(3, 5.0);         // motion 3 anchors nothing here
  EXPECT_EQ(schedule.nextDue_s(), 10.0);
  schedule.motionStarted(2, 7.0);
  EXPECT_DOUBLE_EQ(*schedule.nextDue_s(), 7.1);
  EXPECT_EQ(schedule.takeDue(8.0), std::vector<FaultKind>{FaultKind::kBroadcastDisable});
  EXPECT_EQ(schedule.pending(), 1u);
}

}  // namespace
}  // namespace cyber::plant

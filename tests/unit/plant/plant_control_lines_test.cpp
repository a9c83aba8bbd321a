// The --control FIFO's line splitting of cyber-plant-sim.

#include <gtest/gtest.h>

#include "cyber/plant/control_lines.hpp"

namespace cyber::plant {
namespace {

TEST(ControlLines, SplitsLinesAcrossReadsAndNamesTheKinds) {
  ControlLines lines;
  EXPECT_TRUE(lines.feed("heartbeat-st").empty());
  auto commands = lines.feed("op\n  disable \r\n\nbogus\nsil");
  ASSERT_EQ(commands.size(), 3u);
  EXPECT_EQ(commands[0].kind, FaultKind::kHeartbeatStop);
  EXPECT_EQ(commands[1].kind, FaultKind::kBroadcastDisable);
  EXPECT_EQ(commands[1].line, "disable");
  EXPECT_FALSE(commands[2].kind);
  EXPECT_EQ(commands[2].line, "bogus");
  commands = lines.feed("ent\n");
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0].kind, FaultKind::kSilent);
}

TEST(ControlLines, CutsOverlongLines) {
  ControlLines lines;
  const auto commands = lines.feed(std::string(10000, 'x') + "\nexit\n");
  ASSERT_EQ(commands.size(), 2u);
  EXPECT_EQ(commands[0].line.size(), ControlLines::kMaxLine);
  EXPECT_FALSE(commands[0].kind);
  EXPECT_EQ(commands[1].kind, FaultKind::kExit);
}

TEST(ControlLines, ConditionalFaultsAndProbe) {
  auto command = parseControlLine("  heartbeat-stop if-moving ");
  EXPECT_EQ(command.kind, FaultKind::kHeartbeatStop);
  EXPECT_TRUE(command.if_moving);
  EXPECT_FALSE(command.probe);
  command = parseControlLine("disable");
  EXPECT_EQ(command.kind, FaultKind::kBroadcastDisable);
  EXPECT_FALSE(command.if_moving);
  command = parseControlLine("probe");
  EXPECT_TRUE(command.probe);
  EXPECT_FALSE(command.kind);
  for (const char* bad : {"if-moving", "bogus if-moving", "probe if-moving", "disable if-moving now", "PROBE"}) {
    command = parseControlLine(bad);
    EXPECT_FALSE(command.kind) << bad;
    EXPECT_FALSE(command.probe) << bad;
    EXPECT_FALSE(command.if_moving) << bad;
  }
}

}  // namespace
}  // namespace cyber::plant

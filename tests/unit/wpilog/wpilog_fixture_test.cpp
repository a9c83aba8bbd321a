// The reader on a real log written by WPILib's DataLogManager on a roboRIO in 2022 (public, MIT;
// tests/fixtures/wpilog/README.md). The expected numbers were counted by an independent
// throw-away parser written from the specification, not by this reader.
#include <gtest/gtest.h>

#include "cyber/wpilog/wpilog_reader.hpp"

namespace cyber::wpilog {
namespace {

const Log& fixture() {
  static const auto result = readFile(CYBER_WPILOG_FIXTURE);
  EXPECT_TRUE(result.ok()) << result.error().message;
  return result.value();
}

const Record& last(const Log& log, const char* name) {
  const auto index = log.find(name);
  EXPECT_TRUE(index) << name;
  return *log.recordsOf(*index).back();
}

TEST(WpilogFixture, EveryEntryAndRecordIsRead) {
  const Log& log = fixture();
  EXPECT_EQ(log.version, 0x0100);
  EXPECT_EQ(log.extra_header, "");
  EXPECT_EQ(log.entries.size(), 86u);
  EXPECT_EQ(log.records.size(), 19015u);
  uint64_t latest = 0;
  for (const Record& r : log.records) latest = std::max(latest, r.timestamp_us);
  EXPECT_EQ(latest, 31833768u);
  EXPECT_EQ(log.entries.front().name, "messages");
  EXPECT_EQ(log.entries.front().type, "string");
  EXPECT_EQ(log.entries[1].metadata, R"({"source":"NT"})");
}

TEST(WpilogFixture, EveryRecordDecodesAsItsEntrysType) {
  const Log& log = fixture();
  for (const Record& r : log.records) {
    ASSERT_TRUE(decodesAs(log.entries[r.entry].type, log.payload(r))) << log.entries[r.entry].name;
  }
}

TEST(WpilogFixture, ValuesOfEachTypeAreThoseLogged) {
  const Log& log = fixture();
  EXPECT_EQ(asString(log.payload(last(log, "NT:/SmartDashboard/Autonomous/active"))), "TomatoBalls");
  EXPECT_EQ(asBoolean(log.payload(last(log, "NT:/FMSInfo/IsRedAlliance"))), true);
  EXPECT_EQ(asDouble(log.payload(last(log, "NT:/SmartDashboard/PID/DrivetrainAlign/kP"))), 0.0085);
  EXPECT_EQ(asDouble(log.payload(last(log, "NT:/LiveWindow/Ungrouped/Encoder[0]/Distance"))), 60.804631503521726);
  EXPECT_EQ(last(log, "NT:/LiveWindow/Ungrouped/Encoder[0]/Distance").timestamp_us, 31833768u);
  EXPECT_EQ(log.recordsOf(*log.find("NT:/SmartDashboard/Field/Robot")).size(), 1572u);
  EXPECT_EQ(asDoubleArray(log.payload(last(log, "NT:/SmartDashboard/Field/Robot")))->size(), 3u);
  const auto options = asStringArray(log.payload(last(log, "NT:/SmartDashboard/Autonomous/options")));
  ASSERT_TRUE(options);
  EXPECT_EQ(*options, (std::vector<std::string>{"PID", "BangBang", "Balls", "TomatoBalls"}));
  EXPECT_EQ(log.entries[*log.find("systemTime")].type, "int64");
  EXPECT_EQ(asInt64(log.payload(last(log, "systemTime"))), 1656637475718532);
}

}  // namespace
}  // namespace cyber::wpilog

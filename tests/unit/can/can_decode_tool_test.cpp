// Runs tools/cyber-can-decode on candump -L logs written with the codec and the log writer.

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include "tool_run.hpp"

#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cyber/can/candump_log.hpp"
#include "cyber/can/robot_frames.hpp"
#include "cyber/can/setpoint_codec.hpp"
#include "cyber/can/status_codec.hpp"

namespace cyber::can {
namespace {

using test::readFile;
using test::ToolRun;

std::string tempPath(const std::string& name) {
  return ::testing::TempDir() + "cyber_can_decode_" + std::to_string(::getpid()) + "_" + name;
}

ToolRun runTool(const std::string& args) { return test::runTool(CYBER_CAN_DECODE, args); }

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) out.push_back(line);
  return out;
}

std::vector<std::string> splitCsv(const std::string& row) {
  std::vector<std::string> fields;
  std::istringstream stream(row);
  for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
  if (!row.empty() && row.back() == ',') fields.emplace_back();
  return fields;
}

std::string writeLog(const std::string& name, const std::vector<std::string>& log_lines) {
  const std::string path = tempPath(name);
  std::ofstream file(path);
  for (const auto& line : log_lines) file << line << '\n';
  return path;
}

std::string record(std::uint32_t us, const Frame& frame) {
  return formatLogLine(LogRecord{LogTime{1700000000, us}, "vcan0", frame});
}

// A small log: elevator and arm setpoints, a status, a heartbeat, a disable, a bus error, a
// foreign frame, a short setpoint, a bad status mode, a blank line and a malformed line.
std::vector<std::string> mixedLog() {
  Frame short_setpoint = encodeSetpoint(1, Setpoint{0.1, 0, 0, 1}).value();
  short_setpoint.dlc = 6;
  short_setpoint.data[6] = short_setpoint.data[7] = 0;
  Frame bad_mode = encodeStatus(3, Status{Mode::kHolding, 5, 0, 0, 9}).value();
  bad_mode.data[0] = 7;
  Frame foreign;
  foreign.id = 0x123;
  foreign.dlc = 2;
  foreign.data = {0xDE, 0xAD};
  Frame bus_off;
  bus_off.error = true;
  bus_off.id = 0x40;
  bus_off.dlc = 8;
  return {
      record(0, encodeSetpoint(1, Setpoint{1.23456, 0.5, 1.2, 7}).value()),
      record(50, encodeSetpoint(2, Setpoint{-0.5, -1.25, -0.75, 255}).value()),
      record(100000, encodeStatus(3, Status{Mode::kMoving, 1234, 850, 0, 42}).value()),
      record(20000, encodeHeartbeat(Heartbeat{false, true, false, false, true})),
      record(40000, makeBroadcastDisable()),
      record(50000, bus_off),
      record(60000, foreign),
      record(70000, short_setpoint),
      record(80000, bad_mode),
      "",
      "this is not a candump line",
  };
}

TEST(CanDecodeTool, TextOutput) {
  const std::string path = writeLog("mixed.log", mixedLog());
  const ToolRun run = runTool(path);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const auto out = lines(run.out);
  ASSERT_EQ(out.size(), 9u) << run.out;
  EXPECT_EQ(out[0],
            "1700000000.000000 vcan0 setpoint elevator dev 1 seq 7 position 1.23456 m velocity "
            "0.500 m/s ff 1.200 V");
  EXPECT_EQ(out[1],
            "1700000000.000050 vcan0 setpoint arm dev 2 seq 255 position -0.50000 rad velocity "
            "-1.250 rad/s ff -0.750 V");
  EXPECT_EQ(out[2],
            "1700000000.100000 vcan0 status dev 3 seq 42 mode moving request 1234 remaining 850 ms "
            "faults 0x00");
  EXPECT_EQ(out[3], "1700000000.020000 vcan0 heartbeat enabled=1 watchdog=1 red=0 auto=0 test=0");
  EXPECT_EQ(out[4], "1700000000.040000 vcan0 disable (stop all motion)");
  EXPECT_EQ(out[5], "1700000000.050000 vcan0 bus-error bus-off");
  EXPECT_EQ(out[6], "1700000000.060000 vcan0 other 123#DEAD");
  EXPECT_EQ(out[7].rfind("1700000000.070000 vcan0 undecodable setpoint 0A080401#", 0), 0u) << out[7];
  EXPECT_NE(out[7].find("length"), std::string::npos);
  EXPECT_EQ(out[8].rfind("1700000000.080000 vcan0 undecodable status 0A080803#", 0), 0u) << out[8];
  EXPECT_NE(out[8].find("mode"), std::string::npos);
  EXPECT_NE(run.err.find("line 11: malformed"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("9 frames (6 decoded, 2 undecodable, 1 other), 1 malformed lines"), std::string::npos)
      << run.err;
  std::remove(path.c_str());
}

TEST(CanDecodeTool, CsvOutput) {
  const std::string path = writeLog("mixed_csv.log", mixedLog());
  const ToolRun run = runTool("--csv " + path);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const auto out = lines(run.out);
  ASSERT_EQ(out.size(), 10u);
  EXPECT_EQ(out[0],
            "time_s,iface,kind,device,joint,seq,position,velocity,volts,mode,request_id,"
            "time_remaining_ms,fault_bits,red_alliance,enabled,autonomous,test,system_watchdog,id,"
            "data,error");
  EXPECT_EQ(out[1],
            "1700000000.000000,vcan0,setpoint,1,elevator,7,1.23456,0.500,1.200,,,,,,,,,,0A080401,"
            "40E201F401B00407,");
  EXPECT_EQ(out[3],
            "1700000000.100000,vcan0,status,3,,42,,,,moving,1234,850,0x00,,,,,,0A080803,"
            "02D204520300002A,");
  EXPECT_EQ(out[4], "1700000000.020000,vcan0,heartbeat,,,,,,,,,,,0,1,0,0,1,01011840,0000000012000000,");
  const std::size_t columns = splitCsv(out[0]).size();
  for (std::size_t i = 1; i < out.size(); ++i) {
    EXPECT_EQ(splitCsv(out[i]).size(), columns) << out[i];
  }
  const auto undecodable = splitCsv(out[8]);
  EXPECT_EQ(undecodable[2], "undecodable");
  EXPECT_EQ(undecodable[3], "1");  // the device still comes from the id
  EXPECT_FALSE(undecodable.back().empty());
  std::remove(path.c_str());
}

TEST(CanDecodeTool, RandomSetpointsDecodeToTheirQuantizedValues) {
  std::mt19937 rng(555);
  std::uniform_real_distribution<double> position(-2.0, 2.0), velocity(-5.0, 5.0), volts(-12.0, 12.0);
  std::vector<std::string> log;
  std::vector<Setpoint> sent;
  for (int i = 0; i < 200; ++i) {
    const Setpoint setpoint{position(rng), velocity(rng), volts(rng), static_cast<std::uint8_t>(i)};
    const Frame frame = encodeSetpoint(i % 2 == 0 ? 1 : 2, setpoint).value();
    sent.push_back(decodeSetpoint(frame).value().setpoint);  // what the wire can carry
    log.push_back(record(static_cast<std::uint32_t>(i * 5000), frame));
  }
  const std::string path = writeLog("random.log", log);
  const ToolRun run = runTool("--csv --strict < " + path);  // stdin
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto out = lines(run.out);
  ASSERT_EQ(out.size(), sent.size() + 1);
  for (std::size_t i = 0; i < sent.size(); ++i) {
    const auto fields = splitCsv(out[i + 1]);
    ASSERT_EQ(fields[4], i % 2 == 0 ? "elevator" : "arm");
    ASSERT_EQ(std::stoi(fields[5]), sent[i].sequence);
    ASSERT_EQ(std::stod(fields[6]), sent[i].position) << out[i + 1];
    ASSERT_EQ(std::stod(fields[7]), sent[i].velocity) << out[i + 1];
    ASSERT_EQ(std::stod(fields[8]), sent[i].feedforward_volts) << out[i + 1];
  }
  EXPECT_NE(run.err.find("200 frames (200 decoded, 0 undecodable, 0 other), 0 malformed lines"), std::string::npos);
  std::remove(path.c_str());
}

TEST(CanDecodeTool, JointDevicesFromOptions) {
  const std::string path = writeLog("devices.log", {record(0, encodeSetpoint(5, Setpoint{0.25, 0, 0, 1}).value()),
                                                    record(1, encodeSetpoint(1, Setpoint{0.25, 0, 0, 1}).value())});
  const ToolRun run = runTool("--joint0-device 5 --joint1-device 6 - < " + path);
  EXPECT_EQ(run.exit_code, 0);
  const auto out = lines(run.out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_NE(out[0].find("setpoint elevator dev 5"), std::string::npos) << out[0];
  EXPECT_NE(out[1].find("setpoint dev 1 seq"), std::string::npos) << out[1];  // no joint named
  std::remove(path.c_str());
}

TEST(CanDecodeTool, StrictFailsOnBadFrames) {
  const std::string path = writeLog("strict.log", mixedLog());
  EXPECT_EQ(runTool("--strict " + path).exit_code, 1);
  std::remove(path.c_str());
}

TEST(CanDecodeTool, BadUsageExitsTwo) {
  EXPECT_EQ(runTool("--bogus").exit_code, 2);
  EXPECT_EQ(runTool(tempPath("does_not_exist.log")).exit_code, 2);
  EXPECT_EQ(runTool("--joint1-device 64 /dev/null").exit_code, 2);
  EXPECT_EQ(runTool("--joint1-device x /dev/null").exit_code, 2);
  EXPECT_EQ(runTool("--joint0-device").exit_code, 2);
  EXPECT_EQ(runTool("--config " + tempPath("no_such.toml") + " /dev/null").exit_code, 2);
  EXPECT_EQ(runTool("/dev/null /dev/null").exit_code, 2);
  const ToolRun help = runTool("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("usage: cyber-can-decode"), std::string::npos);
  const ToolRun empty = runTool("/dev/null");
  EXPECT_EQ(empty.exit_code, 0);
  EXPECT_TRUE(empty.out.empty());
}

}  // namespace
}  // namespace cyber::can

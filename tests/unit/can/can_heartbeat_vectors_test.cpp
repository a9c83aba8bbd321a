// The heartbeat test vectors of tests/vectors/heartbeat_frames.txt, both layouts (roboRIO and
// Systemcore), against the C++ codec; the file's header describes the line format.

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cyber/can/candump_log.hpp"
#include "cyber/can/robot_frames.hpp"

namespace cyber::can {
namespace {

struct VectorLine {
  int number = 0;
  std::string kind;
  std::vector<std::string> inputs;    // tokens between the kind and "->"
  std::vector<std::string> expected;  // tokens after "->"
};

std::vector<VectorLine> readVectors() {
  std::ifstream in(CYBER_SOURCE_DIR "/tests/vectors/heartbeat_frames.txt");
  EXPECT_TRUE(in) << "tests/vectors/heartbeat_frames.txt not found";
  std::vector<VectorLine> out;
  std::string text;
  for (int number = 1; std::getline(in, text); ++number) {
    if (text.rfind("#", 0) == 0) continue;
    std::istringstream tokens(text);
    VectorLine line{number, {}, {}, {}};
    if (!(tokens >> line.kind)) continue;
    bool after_arrow = false;
    for (std::string token; tokens >> token;) {
      if (token == "->") {
        after_arrow = true;
      } else {
        (after_arrow ? line.expected : line.inputs).push_back(token);
      }
    }
    out.push_back(line);
  }
  return out;
}

std::vector<VectorLine> linesOf(const std::string& kind) {
  static const auto all = readVectors();
  std::vector<VectorLine> out;
  for (const auto& line : all) {
    if (line.kind == kind) out.push_back(line);
  }
  return out;
}

std::string where(const VectorLine& line) {
  return "tests/vectors/heartbeat_frames.txt:" + std::to_string(line.number);
}

HeartbeatLayout layoutOf(const std::string& name, const VectorLine& line) {
  EXPECT_TRUE(name == "roborio" || name == "systemcore") << where(line) << ": layout " << name;
  return name == "systemcore" ? HeartbeatLayout::kSystemcore : HeartbeatLayout::kRoboRio;
}

Frame parseFrame(const std::string& text, const VectorLine& line) {
  const auto record = parseLogLine("(0.000000) can0 " + text);
  EXPECT_TRUE(record.ok()) << where(line) << ": " << (record.ok() ? "" : record.error().message);
  return record.ok() ? record.value().frame : Frame{};
}

// RED ENABLED AUTO TEST WATCHDOG REPLAY OVERRIDE, from `tokens` starting at `first`.
Heartbeat heartbeatOf(const std::vector<std::string>& tokens, std::size_t first) {
  Heartbeat h;
  h.red_alliance = tokens.at(first) == "1";
  h.enabled = tokens.at(first + 1) == "1";
  h.autonomous = tokens.at(first + 2) == "1";
  h.test = tokens.at(first + 3) == "1";
  h.system_watchdog = tokens.at(first + 4) == "1";
  h.replay_number = static_cast<std::uint8_t>(std::stoi(tokens.at(first + 5)));
  h.ftc_motor_override = tokens.at(first + 6) == "1";
  return h;
}

// What the motion gate takes from a heartbeat (daemon/core/src/motion_gate.cpp): the override closes
// it before the watchdog bit is looked at.
std::string gateOf(const Heartbeat& h) {
  if (h.ftc_motor_override) return "override";
  return h.system_watchdog ? "open" : "disabled";
}

const std::map<std::string, CodecError>& errorNames() {
  static const std::map<std::string, CodecError> names = {
      {"wrong-id", CodecError::kWrongId},         {"not-extended", CodecError::kNotExtended},
      {"remote-frame", CodecError::kRemoteFrame}, {"error-frame", CodecError::kErrorFrame},
      {"wrong-length", CodecError::kWrongLength},
  };
  return names;
}

TEST(HeartbeatVectors, Decode) {
  const auto lines = linesOf("decode-heartbeat");
  ASSERT_GE(lines.size(), 30u);
  for (const auto& line : lines) {
    ASSERT_EQ(line.inputs.size(), 2u) << where(line);
    const auto decoded = decodeHeartbeat(parseFrame(line.inputs[1], line), layoutOf(line.inputs[0], line));
    if (line.expected.at(0) == "error") {
      ASSERT_EQ(line.expected.size(), 2u) << where(line);
      ASSERT_FALSE(decoded.ok()) << where(line);
      EXPECT_EQ(decoded.status(), errorNames().at(line.expected[1])) << where(line);
      continue;
    }
    ASSERT_EQ(line.expected.size(), 8u) << where(line);
    ASSERT_TRUE(decoded.ok()) << where(line);
    EXPECT_EQ(decoded.value(), heartbeatOf(line.expected, 0)) << where(line);
    EXPECT_EQ(gateOf(decoded.value()), line.expected[7]) << where(line);
  }
}

TEST(HeartbeatVectors, Encode) {
  const auto lines = linesOf("encode-heartbeat");
  ASSERT_GE(lines.size(), 6u);
  for (const auto& line : lines) {
    ASSERT_EQ(line.inputs.size(), 8u) << where(line);
    ASSERT_EQ(line.expected.size(), 1u) << where(line);
    const HeartbeatLayout layout = layoutOf(line.inputs[0], line);
    const Frame encoded = encodeHeartbeat(heartbeatOf(line.inputs, 1), layout);
    EXPECT_EQ(encoded, parseFrame(line.expected[0], line)) << where(line);
  }
}

TEST(HeartbeatVectors, EveryErrorAndBothLayoutsAreCovered) {
  std::map<std::string, int> layouts;
  std::map<std::string, int> errors;
  std::map<std::string, int> gates;
  for (const auto& line : linesOf("decode-heartbeat")) {
    ++layouts[line.inputs.at(0)];
    if (line.expected.at(0) == "error") {
      ++errors[line.expected.at(1)];
    } else {
      ++gates[line.expected.at(7)];
    }
  }
  EXPECT_GE(layouts["roborio"], 10);
  EXPECT_GE(layouts["systemcore"], 10);
  for (const auto& [name, error] : errorNames()) EXPECT_GE(errors[name], 1) << name;
  for (const char* gate : {"open", "disabled", "override"}) EXPECT_GE(gates[gate], 1) << gate;
}

}  // namespace
}  // namespace cyber::can

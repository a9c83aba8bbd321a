// The shared test vectors of tests/vectors/can_frames.txt against the C++ codec (the source of
// truth of the format). The Java decoder of roborio/ reads the same file, so the two cannot drift
// apart; the file's header describes the line format.

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cyber/can/candump_log.hpp"
#include "cyber/can/setpoint_codec.hpp"
#include "cyber/can/status_codec.hpp"

namespace cyber::can {
namespace {

struct VectorLine {
  int number = 0;
  std::vector<std::string> inputs;    // tokens between the kind and "->"
  std::vector<std::string> expected;  // tokens after "->"
};

std::map<std::string, std::vector<VectorLine>> readVectors() {
  std::ifstream in(CYBER_SOURCE_DIR "/tests/vectors/can_frames.txt");
  EXPECT_TRUE(in) << "tests/vectors/can_frames.txt not found";
  std::map<std::string, std::vector<VectorLine>> out;
  std::string text;
  for (int number = 1; std::getline(in, text); ++number) {
    if (text.rfind("#", 0) == 0) continue;
    std::istringstream tokens(text);
    std::string kind, token;
    if (!(tokens >> kind)) continue;
    VectorLine line{number, {}, {}};
    bool after_arrow = false;
    while (tokens >> token) {
      if (token == "->") {
        after_arrow = true;
      } else {
        (after_arrow ? line.expected : line.inputs).push_back(token);
      }
    }
    out[kind].push_back(line);
  }
  return out;
}

const std::map<std::string, std::vector<VectorLine>>& vectors() {
  static const auto all = readVectors();
  return all;
}

const std::map<std::string, CodecError>& errorNames() {
  static const std::map<std::string, CodecError> names = {
      {"device-out-of-range", CodecError::kDeviceOutOfRange},
      {"position-out-of-range", CodecError::kPositionOutOfRange},
      {"velocity-out-of-range", CodecError::kVelocityOutOfRange},
      {"voltage-out-of-range", CodecError::kVoltageOutOfRange},
      {"bad-mode", CodecError::kBadMode},
      {"wrong-id", CodecError::kWrongId},
      {"not-extended", CodecError::kNotExtended},
      {"remote-frame", CodecError::kRemoteFrame},
      {"error-frame", CodecError::kErrorFrame},
      {"wrong-length", CodecError::kWrongLength},
  };
  return names;
}

std::string where(const VectorLine& line) { return "tests/vectors/can_frames.txt:" + std::to_string(line.number); }

Frame parseFrame(const std::string& text, const VectorLine& line) {
  const auto record = parseLogLine("(0.000000) can0 " + text);
  EXPECT_TRUE(record.ok()) << where(line) << ": " << (record.ok() ? "" : record.error().message);
  return record.ok() ? record.value().frame : Frame{};
}

std::string formatFrame(const Frame& frame) {
  const std::string line = formatLogLine(LogRecord{LogTime{}, "can0", frame});
  return line.substr(line.find(' ', line.find(' ') + 1) + 1);
}

long long integer(const std::string& text) { return std::stoll(text, nullptr, 0); }
double number(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

// An expected "error NAME", or the frame/values otherwise.
template <typename T>
void expectOutcome(const Result<T, CodecError>& result, const VectorLine& line,
                   const std::function<void(const T&)>& check_value) {
  ASSERT_FALSE(line.expected.empty()) << where(line);
  if (line.expected[0] == "error") {
    ASSERT_EQ(line.expected.size(), 2u) << where(line);
    ASSERT_TRUE(errorNames().count(line.expected[1])) << where(line) << ": unknown error name";
    ASSERT_FALSE(result.ok()) << where(line) << ": expected " << line.expected[1];
    EXPECT_EQ(result.status(), errorNames().at(line.expected[1]))
        << where(line) << ": got " << toString(result.status());
  } else {
    ASSERT_TRUE(result.ok()) << where(line) << ": " << toString(result.status());
    check_value(result.value());
  }
}

TEST(SharedVectors, FileHasEveryKindAndEveryErrorName) {
  for (const char* kind : {"encode-setpoint", "decode-setpoint", "encode-status", "decode-status", "request-low16"}) {
    EXPECT_GE(vectors().count(kind) ? vectors().at(kind).size() : 0u, 3u) << kind;
  }
  EXPECT_EQ(vectors().size(), 5u) << "an unknown kind of line";
  for (const auto& [name, error] : errorNames()) {
    bool seen = false;
    for (const auto& [kind, lines] : vectors()) {
      for (const auto& line : lines) seen = seen || (line.expected.size() == 2 && line.expected[1] == name);
    }
    EXPECT_TRUE(seen) << "no vector expects " << name;
  }
}

TEST(SharedVectors, EncodeSetpoint) {
  for (const auto& line : vectors().at("encode-setpoint")) {
    ASSERT_EQ(line.inputs.size(), 5u) << where(line);
    const auto device = static_cast<std::uint8_t>(integer(line.inputs[0]));
    ASSERT_EQ(integer(line.inputs[0]), device) << where(line);
    const Setpoint setpoint{number(line.inputs[1]), number(line.inputs[2]), number(line.inputs[3]),
                            static_cast<std::uint8_t>(integer(line.inputs[4]))};
    expectOutcome<Frame>(encodeSetpoint(device, setpoint), line, [&](const Frame& frame) {
      EXPECT_EQ(formatFrame(frame), line.expected.at(0)) << where(line);
    });
  }
}

TEST(SharedVectors, DecodeSetpoint) {
  for (const auto& line : vectors().at("decode-setpoint")) {
    ASSERT_EQ(line.inputs.size(), 1u) << where(line);
    expectOutcome<DeviceSetpoint>(decodeSetpoint(parseFrame(line.inputs[0], line)), line, [&](const DeviceSetpoint& d) {
      ASSERT_EQ(line.expected.size(), 5u) << where(line);
      EXPECT_EQ(d.device, integer(line.expected[0])) << where(line);
      EXPECT_EQ(d.setpoint.position, integer(line.expected[1]) / kPositionCountsPerUnit) << where(line);
      EXPECT_EQ(d.setpoint.velocity, integer(line.expected[2]) / kVelocityCountsPerUnit) << where(line);
      EXPECT_EQ(d.setpoint.feedforward_volts, integer(line.expected[3]) / kVoltageCountsPerVolt) << where(line);
      EXPECT_EQ(d.setpoint.sequence, integer(line.expected[4])) << where(line);
    });
  }
}

TEST(SharedVectors, EncodeStatus) {
  for (const auto& line : vectors().at("encode-status")) {
    ASSERT_EQ(line.inputs.size(), 6u) << where(line);
    const auto device = static_cast<std::uint8_t>(integer(line.inputs[0]));
    const Status status{static_cast<Mode>(integer(line.inputs[1])), static_cast<std::uint16_t>(integer(line.inputs[2])),
                        static_cast<std::uint16_t>(integer(line.inputs[3])),
                        static_cast<std::uint8_t>(integer(line.inputs[4])),
                        static_cast<std::uint8_t>(integer(line.inputs[5]))};
    expectOutcome<Frame>(encodeStatus(device, status), line, [&](const Frame& frame) {
      EXPECT_EQ(formatFrame(frame), line.expected.at(0)) << where(line);
    });
  }
}

TEST(SharedVectors, DecodeStatus) {
  for (const auto& line : vectors().at("decode-status")) {
    ASSERT_EQ(line.inputs.size(), 1u) << where(line);
    expectOutcome<DeviceStatus>(decodeStatus(parseFrame(line.inputs[0], line)), line, [&](const DeviceStatus& d) {
      ASSERT_EQ(line.expected.size(), 6u) << where(line);
      EXPECT_EQ(d.device, integer(line.expected[0])) << where(line);
      EXPECT_EQ(static_cast<int>(d.status.mode), integer(line.expected[1])) << where(line);
      EXPECT_EQ(d.status.request_id, integer(line.expected[2])) << where(line);
      EXPECT_EQ(d.status.time_remaining_ms, integer(line.expected[3])) << where(line);
      EXPECT_EQ(d.status.fault_bits, integer(line.expected[4])) << where(line);
      EXPECT_EQ(d.status.sequence, integer(line.expected[5])) << where(line);
    });
  }
}

TEST(SharedVectors, RequestIdLow16) {
  for (const auto& line : vectors().at("request-low16")) {
    ASSERT_EQ(line.inputs.size(), 1u) << where(line);
    EXPECT_EQ(requestIdLow16(integer(line.inputs[0])), integer(line.expected.at(0))) << where(line);
  }
}

}  // namespace
}  // namespace cyber::can

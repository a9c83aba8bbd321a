#include <gtest/gtest.h>

#include <random>
#include <string>

#include "cyber/can/candump_log.hpp"
#include "random_frame.hpp"

namespace cyber::can {
namespace {

Frame extendedFrame(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
  Frame frame;
  frame.id = id;
  frame.extended = true;
  for (std::uint8_t b : bytes) frame.data[frame.dlc++] = b;
  return frame;
}

LogRecord parseOk(std::string_view line) {
  const auto record = parseLogLine(line);
  EXPECT_TRUE(record.ok()) << line << ": " << (record.ok() ? "" : record.error().message);
  return record.ok() ? record.value() : LogRecord{};
}

TEST(CandumpLog, FormatsLikeCandump) {
  LogRecord record{{1700000000, 123456}, "vcan0", extendedFrame(0x0A080040u, {1, 2, 3, 4, 5, 6, 7, 8})};
  EXPECT_EQ(formatLogLine(record), "(1700000000.123456) vcan0 0A080040#0102030405060708");

  Frame standard;
  standard.id = 0x7B;
  standard.dlc = 2;
  standard.data[0] = 0xAB;
  standard.data[1] = 0x0C;
  EXPECT_EQ(formatLogLine(LogRecord{{5, 7}, "can0", standard}), "(0000000005.000007) can0 07B#AB0C");

  Frame empty = extendedFrame(0, {});
  EXPECT_EQ(formatLogLine(LogRecord{{1, 0}, "can0", empty}), "(0000000001.000000) can0 00000000#");

  Frame remote;
  remote.id = 0x123;
  remote.remote = true;
  EXPECT_EQ(formatLogLine(LogRecord{{1, 0}, "can0", remote}), "(0000000001.000000) can0 123#R");
  remote.dlc = 8;
  EXPECT_EQ(formatLogLine(LogRecord{{1, 0}, "can0", remote}), "(0000000001.000000) can0 123#R8");

  Frame error;
  error.error = true;
  error.id = 0x40;  // CAN_ERR_BUSOFF
  error.dlc = 8;
  EXPECT_EQ(formatLogLine(LogRecord{{1, 0}, "can0", error}), "(0000000001.000000) can0 20000040#0000000000000000");
}

TEST(CandumpLog, ParsesCandumpLines) {
  const LogRecord record = parseOk("(1700000000.123456) vcan0 0A080040#0102030405060708");
  EXPECT_EQ(record.time, (LogTime{1700000000, 123456}));
  EXPECT_DOUBLE_EQ(record.time.toSeconds(), 1700000000.123456);
  EXPECT_EQ(record.iface, "vcan0");
  EXPECT_EQ(record.frame, extendedFrame(0x0A080040u, {1, 2, 3, 4, 5, 6, 7, 8}));

  const LogRecord standard = parseOk("(0000000005.000007) can0 07b#ab.0c\r\n");
  EXPECT_FALSE(standard.frame.extended);
  EXPECT_EQ(standard.frame.id, 0x7Bu);
  EXPECT_EQ(standard.frame.dlc, 2);
  EXPECT_EQ(standard.frame.data[0], 0xAB);
  EXPECT_EQ(standard.frame.data[1], 0x0C);

  const LogRecord remote = parseOk("(1.000000) can0 123#R5");
  EXPECT_TRUE(remote.frame.remote);
  EXPECT_EQ(remote.frame.dlc, 5);

  const LogRecord error = parseOk("(1.000000) can0 20000004#0010000000000000");
  EXPECT_TRUE(error.frame.error);
  EXPECT_FALSE(error.frame.extended);
  EXPECT_EQ(error.frame.id, 0x4u);
  EXPECT_EQ(error.frame.data[1], 0x10);

  const LogRecord direction = parseOk("(1.000000) can0 00000000# T");
  EXPECT_TRUE(direction.frame.extended);
  EXPECT_EQ(direction.frame.dlc, 0);
}

TEST(CandumpLog, RandomRecordsRoundTrip) {
  std::mt19937_64 rng(123);
  std::uniform_int_distribution<int> name_length(1, 15);
  std::uniform_int_distribution<std::uint64_t> seconds(0, 9999999999ull);
  std::uniform_int_distribution<std::uint32_t> micros(0, 999999), letter(0, 25);
  for (int i = 0; i < 5000; ++i) {
    LogRecord record;
    record.time = LogTime{seconds(rng), micros(rng)};
    const int length = name_length(rng);
    for (int c = 0; c < length; ++c) record.iface.push_back(static_cast<char>('a' + letter(rng)));
    record.frame = test::randomFrame(rng);
    const std::string line = formatLogLine(record);
    const auto parsed = parseLogLine(line);
    ASSERT_TRUE(parsed.ok()) << line << ": " << parsed.error().message;
    ASSERT_EQ(parsed.value(), record) << line;
    ASSERT_EQ(formatLogLine(parsed.value()), line);
  }
}

TEST(CandumpLog, RejectsMalformedLines) {
  const char* bad[] = {
      "",
      "   ",
      "vcan0 123#00",                                      // no timestamp
      "(1700000000.123456)",                               // nothing after the time
      "(1700000000.123456) vcan0",                         // no frame
      "1700000000.123456 vcan0 123#00",                    // no parentheses
      "(1700000000.12345) vcan0 123#00",                   // 5 fraction digits
      "(1700000000.1234567) vcan0 123#00",                 // 7 fraction digits
      "(17000x0000.123456) vcan0 123#00",                  // non-digit in time
      "(.123456) vcan0 123#00",                            // no seconds
      "(1700000000.123456) vcan0 12#00",                   // 2-digit id
      "(1700000000.123456) vcan0 1234#00",                 // 4-digit id
      "(1700000000.123456) vcan0 800#00",                  // standard id above 0x7FF
      "(1700000000.123456) vcan0 4A080040#00",             // flag bit 0x40000000 set
      "(1700000000.123456) vcan0 G23#00",                  // non-hex id
      "(1700000000.123456) vcan0 123",                     // no '#'
      "(1700000000.123456) vcan0 123#0",                   // odd digit count
      "(1700000000.123456) vcan0 123#0G",                  // non-hex data
      "(1700000000.123456) vcan0 123#010203040506070809",  // 9 bytes
      "(1700000000.123456) vcan0 123#.01",                 // leading '.'
      "(1700000000.123456) vcan0 123#01.",                 // trailing '.'
      "(1700000000.123456) vcan0 123#01..02",              // double '.'
      "(1700000000.123456) vcan0 123##1020304",            // CAN FD
      "(1700000000.123456) vcan0 123#R9",                  // remote length 9
      "(1700000000.123456) vcan0 123#R12",                 // remote length two digits
      "(1700000000.123456) vcan0 20000004#R",              // remote error frame
      "(1700000000.123456) vcan0 123#00 X",                // junk after the frame
      "(1700000000.123456) vcan0 123#00 T extra",          // junk after the direction
      "(1700000000.123456) averyveryverylongname 123#00",  // 21-character interface
      "(1700000000.040000) c0#\n 09000000#\n",             // line break in the interface (fuzz reproducer)
      "(1700000000.123456) vcan\r0 123#00",                // control character in the interface
      "(1700000000.123456) vcan\x7f 123#00",               // DEL in the interface
  };
  for (const char* line : bad) {
    const auto parsed = parseLogLine(line);
    EXPECT_EQ(parsed.status(), LogParseError::kMalformed) << "accepted: " << line;
    if (!parsed.ok()) {
      EXPECT_FALSE(parsed.error().message.empty()) << line;
    }
  }
}

}  // namespace
}  // namespace cyber::can

#pragma once
// The one-line-per-frame log format of can-utils' `candump -L` (also read by canplayer):
//
//   (1700000000.123456) vcan0 0A080041#3930000000000000
//
// Timestamp seconds.microseconds in parentheses (seconds zero-padded to 10 digits, microseconds
// always 6), interface name, then the frame: the id in hex, 3 digits for a standard id and 8 for an
// extended one (an error frame is 8 digits with CAN_ERR_FLAG 0x20000000 set), '#', and the data as
// two upper-case hex digits per byte. A remote request is written `R`, followed by its length digit
// when that is not 0. Parsing also accepts lower-case hex, '.' between data bytes, and a trailing
// direction token `T` or `R` written by newer can-utils. CAN FD frames (`##`) are rejected.

#include <cstdint>
#include <string>
#include <string_view>

#include "cyber/can/frame.hpp"
#include "cyber/result.hpp"

namespace cyber::can {

struct LogTime {
  std::uint64_t seconds = 0;
  std::uint32_t microseconds = 0;  // 0..999999

  double toSeconds() const { return static_cast<double>(seconds) + microseconds * 1e-6; }
  bool operator==(const LogTime&) const = default;
};

struct LogRecord {
  LogTime time;
  std::string iface;  // 1..15 characters, no white space
  Frame frame;

  bool operator==(const LogRecord&) const = default;
};

// A line that is not a frame of this format; the message says what is wrong with it.
enum class LogParseError { kOk, kMalformed };

// One line without its newline. Expects a well-formed frame (isWellFormed) and microseconds below
// one million (a larger value carries into the seconds).
std::string formatLogLine(const LogRecord& record);

// Parses one line (a trailing "\n" or "\r\n" is allowed).
Result<LogRecord, LogParseError> parseLogLine(std::string_view line);

}  // namespace cyber::can

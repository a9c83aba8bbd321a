#include "cyber/can/candump_log.hpp"

#include <fmt/format.h>
#include <linux/can.h>

#include <iterator>
#include <optional>

namespace cyber::can {

namespace {

constexpr std::size_t kMaxIfaceLength = 15;  // IFNAMSIZ - 1
constexpr char kHexDigits[] = "0123456789ABCDEF";

std::optional<unsigned> hexValue(char c) {
  if (c >= '0' && c <= '9') return static_cast<unsigned>(c - '0');
  if (c >= 'A' && c <= 'F') return static_cast<unsigned>(c - 'A' + 10);
  if (c >= 'a' && c <= 'f') return static_cast<unsigned>(c - 'a' + 10);
  return std::nullopt;
}

bool isBlank(char c) { return c == ' ' || c == '\t'; }

void appendHex(std::string& out, std::uint32_t value, int digits) {
  for (int shift = 4 * (digits - 1); shift >= 0; shift -= 4) {
    out.push_back(kHexDigits[(value >> shift) & 0xFu]);
  }
}

Error<LogParseError> fail(std::string reason) {
  return Error<LogParseError>{LogParseError::kMalformed, std::move(reason)};
}

// Splits off the next blank-separated token; rest starts after it.
std::string_view nextToken(std::string_view& rest) {
  std::size_t begin = 0;
  while (begin < rest.size() && isBlank(rest[begin])) ++begin;
  std::size_t end = begin;
  while (end < rest.size() && !isBlank(rest[end])) ++end;
  const std::string_view token = rest.substr(begin, end - begin);
  rest.remove_prefix(end);
  return token;
}

Result<LogTime, LogParseError> parseTime(std::string_view token) {
  if (token.size() < 4 || token.front() != '(' || token.back() != ')') {
    return fail("timestamp must look like (seconds.microseconds)");
  }
  const std::string_view inner = token.substr(1, token.size() - 2);
  const std::size_t dot = inner.find('.');
  if (dot == std::string_view::npos || dot == 0 || dot > 19) {
    return fail("timestamp must have 1 to 19 digits of seconds before '.'");
  }
  if (inner.size() - dot - 1 != 6) return fail("timestamp must have exactly 6 digits after '.'");
  LogTime time;
  for (std::size_t i = 0; i < inner.size(); ++i) {
    if (i == dot) continue;
    const char c = inner[i];
    if (c < '0' || c > '9') return fail("timestamp has a non-digit character");
    const unsigned digit = static_cast<unsigned>(c - '0');
    if (i < dot) {
      time.seconds = time.seconds * 10 + digit;
    } else {
      time.microseconds = time.microseconds * 10 + digit;
    }
  }
  return time;
}

Result<Frame, LogParseError> parseFrame(std::string_view token) {
  const std::size_t hash = token.find('#');
  if (hash == std::string_view::npos) return fail("frame has no '#' after the id");
  const std::string_view id_text = token.substr(0, hash);
  if (id_text.size() != 3 && id_text.size() != 8) {
    return fail("frame id must have 3 (standard) or 8 (extended) hex digits");
  }
  std::uint32_t raw_id = 0;
  for (char c : id_text) {
    const auto digit = hexValue(c);
    if (!digit) return fail("frame id has a non-hex character");
    raw_id = (raw_id << 4) | *digit;
  }
  Frame frame;
  if (id_text.size() == 3) {
    if (raw_id > CAN_SFF_MASK) return fail("standard id above 0x7FF");
    frame.id = raw_id;
  } else if ((raw_id & CAN_ERR_FLAG) != 0) {
    if ((raw_id & (CAN_EFF_FLAG | CAN_RTR_FLAG)) != 0) return fail("error frame id with flag bits");
    frame.error = true;
    frame.id = raw_id & CAN_ERR_MASK;
  } else {
    if (raw_id > CAN_EFF_MASK) return fail("extended id above 0x1FFFFFFF");
    frame.extended = true;
    frame.id = raw_id;
  }

  std::string_view payload = token.substr(hash + 1);
  if (!payload.empty() && payload.front() == '#') return fail("CAN FD frames are not supported");
  if (!payload.empty() && (payload.front() == 'R' || payload.front() == 'r')) {
    if (frame.error) return fail("error frames cannot be remote requests");
    frame.remote = true;
    payload.remove_prefix(1);
    if (payload.empty()) return frame;
    const auto length = hexValue(payload.front());
    if (payload.size() != 1 || !length || *length > kMaxDataLength) {
      return fail("remote request length must be one digit 0..8");
    }
    frame.dlc = static_cast<std::uint8_t>(*length);
    return frame;
  }
  std::size_t i = 0;
  while (i < payload.size()) {
    if (payload[i] == '.') {
      // A separator only between two bytes.
      if (i == 0 || i + 1 >= payload.size() || payload[i + 1] == '.') {
        return fail("misplaced '.' in data");
      }
      ++i;
      continue;
    }
    if (i + 1 >= payload.size()) return fail("data has an odd number of hex digits");
    const auto high = hexValue(payload[i]);
    const auto low = hexValue(payload[i + 1]);
    if (!high || !low) return fail("data has a non-hex character");
    if (frame.dlc == kMaxDataLength) return fail("more than 8 data bytes");
    frame.data[frame.dlc++] = static_cast<std::uint8_t>((*high << 4) | *low);
    i += 2;
  }
  return frame;
}

}  // namespace

std::string formatLogLine(const LogRecord& record) {
  const std::uint64_t seconds = record.time.seconds + record.time.microseconds / 1000000u;
  const std::uint32_t micros = record.time.microseconds % 1000000u;
  std::string line;
  fmt::format_to(std::back_inserter(line), "({:010}.{:06}) {} ", seconds, micros, record.iface);

  const Frame& frame = record.frame;
  if (frame.error) {
    appendHex(line, (frame.id & CAN_ERR_MASK) | CAN_ERR_FLAG, 8);
  } else if (frame.extended) {
    appendHex(line, frame.id & CAN_EFF_MASK, 8);
  } else {
    appendHex(line, frame.id & CAN_SFF_MASK, 3);
  }
  line.push_back('#');
  if (frame.remote && !frame.error) {
    line.push_back('R');
    if (frame.dlc > 0) line.push_back(kHexDigits[frame.dlc & 0xFu]);
    return line;
  }
  const std::uint8_t length = frame.dlc <= kMaxDataLength ? frame.dlc : kMaxDataLength;
  for (std::uint8_t i = 0; i < length; ++i) appendHex(line, frame.data[i], 2);
  return line;
}

Result<LogRecord, LogParseError> parseLogLine(std::string_view line) {
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.remove_suffix(1);
  std::string_view rest = line;
  const std::string_view time_token = nextToken(rest);
  if (time_token.empty()) return fail("empty line");
  auto time = parseTime(time_token);
  if (!time) return time.error();
  const std::string_view iface = nextToken(rest);
  const std::string_view frame_token = nextToken(rest);
  if (frame_token.empty()) return fail("expected: (time) interface id#data");
  if (iface.size() > kMaxIfaceLength) return fail("interface name longer than 15 characters");
  // Blanks end the token; any other control character (a line break inside the line, found by
  // tests/fuzz/candump_line) would make a record that formats as something else.
  for (const char c : iface) {
    if (c <= ' ' || c > '~') return fail("interface name with a character that is not printable ASCII");
  }
  const std::string_view direction = nextToken(rest);
  if (!direction.empty() && direction != "T" && direction != "R") {
    return fail("unexpected text after the frame");
  }
  if (!nextToken(rest).empty()) return fail("unexpected text after the frame");
  auto frame = parseFrame(frame_token);
  if (!frame) return frame.error();
  return LogRecord{time.value(), std::string(iface), frame.value()};
}

}  // namespace cyber::can

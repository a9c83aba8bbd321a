#pragma once
// One candump -L record decoded into a readable line or a CSV row.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "cyber/can/candump_log.hpp"

namespace cyber::tools {

enum class OutputFormat { kText, kCsv };

// Which device numbers are the joints, and their names and units (from the config's
// [daemon.devices] and [[joints]]; the defaults are the reference robot's).
struct JointDevices {
  std::vector<std::uint8_t> devices{1, 2};  // by joint index
  std::vector<std::string> names{"elevator", "arm"};
  std::vector<std::string> units{"m", "rad"};  // "m" (prismatic) or "rad" (revolute)
};

struct DecodeCounts {
  long frames = 0;       // well-formed log lines
  long decoded = 0;      // setpoint, status, heartbeat, disable, bus error decoded
  long undecodable = 0;  // one of our ids with a payload its decoder rejects
  long other = 0;        // frames that are not part of the protocol
  long malformed = 0;    // lines that are not candump -L records
};

std::string csvHeader();

// Decodes one record, counts it, and returns its output line (without newline).
std::string decodeRecord(const can::LogRecord& record, const JointDevices& joints, OutputFormat format,
                         DecodeCounts& counts);

}  // namespace cyber::tools

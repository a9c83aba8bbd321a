#pragma once
// One candump -L record decoded into a readable line or a CSV row.

#include <cstdint>
#include <string>

#include "cyber/can/candump_log.hpp"

namespace cyber::tools {

enum class OutputFormat { kText, kCsv };

// Which device numbers are the joints (from the [daemon] config section; defaults 1 and 2).
struct JointDevices {
  std::uint8_t elevator = 1;
  std::uint8_t arm = 2;
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

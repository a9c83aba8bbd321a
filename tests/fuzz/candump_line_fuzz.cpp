// Fuzz target: one `candump -L` line (the input, whole) through parseLogLine, then through
// cyber-can-decode's decodeRecord as text and CSV.
// Properties: a parsed record holds a well-formed frame, an interface of 1..15 characters without
// white space and microseconds below one million; formatting it gives a line that parses to the
// same record; a line that fails has a reason; decodeRecord counts every record exactly once.

#include <string>

#include "cyber/can/candump_log.hpp"
#include "decoded_line.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  const auto parsed = cyber::can::parseLogLine(line);
  if (!parsed) {
    CYBER_FUZZ_CHECK(!parsed.error().message.empty());
    return 0;
  }
  const cyber::can::LogRecord& record = parsed.value();
  CYBER_FUZZ_CHECK(cyber::can::isWellFormed(record.frame));
  CYBER_FUZZ_CHECK(!record.iface.empty() && record.iface.size() <= 15);
  CYBER_FUZZ_CHECK(record.iface.find_first_of(" \t\r\n") == std::string::npos);
  CYBER_FUZZ_CHECK(record.time.microseconds < 1'000'000);

  const std::string formatted = cyber::can::formatLogLine(record);
  const auto again = cyber::can::parseLogLine(formatted);
  CYBER_FUZZ_CHECK(again && again.value() == record);
  CYBER_FUZZ_CHECK(cyber::can::formatLogLine(again.value()) == formatted);

  for (const auto format : {cyber::tools::OutputFormat::kText, cyber::tools::OutputFormat::kCsv}) {
    cyber::tools::DecodeCounts counts;
    const std::string out = cyber::tools::decodeRecord(record, cyber::tools::JointDevices{}, format, counts);
    CYBER_FUZZ_CHECK(!out.empty() && out.find('\n') == std::string::npos);
    CYBER_FUZZ_CHECK(counts.frames == 1 && counts.decoded + counts.undecodable + counts.other == 1);
  }
  return 0;
}

#pragma once
// Reads WPILib data log (.wpilog) files, version 1.0: the entries a log starts and the records
// that refer to them, with a status for every malformed input (docs/operations.md,
// "AdvantageScope").

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cyber/result.hpp"
#include "cyber/wpilog/wpilog_status.hpp"

namespace cyber::wpilog {

struct Entry {
  uint32_t id = 0;
  std::string name;
  std::string type;
  std::string metadata;  // the latest Set Metadata, else the Start's
  uint64_t start_timestamp_us = 0;
};

struct Record {
  size_t entry = 0;  // index into Log::entries
  uint64_t timestamp_us = 0;
  size_t offset = 0;  // payload position in Log::bytes
  size_t size = 0;
};

struct Log {
  uint16_t version = 0;
  std::string extra_header;
  std::vector<uint8_t> bytes;
  std::vector<Entry> entries;   // in the order they were started (an id reused after Finish is a new entry)
  std::vector<Record> records;  // data records in file order; control records are folded into entries

  [[nodiscard]] std::span<const uint8_t> payload(const Record& r) const { return {bytes.data() + r.offset, r.size}; }
  // Index of the first entry named `name`, if any.
  [[nodiscard]] std::optional<size_t> find(std::string_view name) const;
  // The records of entry `index`, in file order.
  [[nodiscard]] std::vector<const Record*> recordsOf(size_t index) const;
};

// A malformed file is one of kBadMagic .. kUnknownEntry; readFile's messages start with the path.
Result<Log, WpilogStatus> parse(std::vector<uint8_t> bytes);
Result<Log, WpilogStatus> readFile(const std::string& path);

// Payload decoders for the standard types; nullopt when the size does not fit the type.
std::optional<bool> asBoolean(std::span<const uint8_t> payload);
std::optional<int64_t> asInt64(std::span<const uint8_t> payload);
std::optional<float> asFloat(std::span<const uint8_t> payload);
std::optional<double> asDouble(std::span<const uint8_t> payload);
std::string asString(std::span<const uint8_t> payload);
std::optional<std::vector<bool>> asBooleanArray(std::span<const uint8_t> payload);
std::optional<std::vector<int64_t>> asInt64Array(std::span<const uint8_t> payload);
std::optional<std::vector<float>> asFloatArray(std::span<const uint8_t> payload);
std::optional<std::vector<double>> asDoubleArray(std::span<const uint8_t> payload);
std::optional<std::vector<std::string>> asStringArray(std::span<const uint8_t> payload);
// Whether a payload decodes as the entry's type (standard types; other types are not checked).
bool decodesAs(std::string_view type, std::span<const uint8_t> payload);

}  // namespace cyber::wpilog

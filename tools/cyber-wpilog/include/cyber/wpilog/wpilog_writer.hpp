#pragma once
// Writes WPILib data log (.wpilog) files, version 1.0 (the format and what the project logs: docs/operations.md,
// "AdvantageScope"): entries are started with a name, a type string and metadata, then carry timestamped records. The
// whole file is built in memory; this is a tool, not the streaming path.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cyber/result.hpp"
#include "cyber/wpilog/wpilog_status.hpp"

namespace cyber::wpilog {

class Writer {
 public:
  explicit Writer(std::string_view extra_header = "");

  // Starts an entry and returns its id (1, 2, ...; 0 is the control entry).
  uint32_t start(std::string_view name, std::string_view type, std::string_view metadata, uint64_t timestamp_us);
  void finish(uint32_t entry, uint64_t timestamp_us);
  void setMetadata(uint32_t entry, std::string_view metadata, uint64_t timestamp_us);
  // Publishes a struct schema as the entry "/.schema/struct:NAME" of type "structschema", the
  // way WPILib announces the layout of "struct:NAME" entries.
  void addStructSchema(std::string_view struct_name, std::string_view schema, uint64_t timestamp_us);

  void appendRaw(uint32_t entry, uint64_t timestamp_us, std::span<const uint8_t> payload);
  void appendBoolean(uint32_t entry, uint64_t timestamp_us, bool value);
  void appendInt64(uint32_t entry, uint64_t timestamp_us, int64_t value);
  void appendFloat(uint32_t entry, uint64_t timestamp_us, float value);
  void appendDouble(uint32_t entry, uint64_t timestamp_us, double value);
  void appendString(uint32_t entry, uint64_t timestamp_us, std::string_view value);
  void appendBooleanArray(uint32_t entry, uint64_t timestamp_us, std::span<const bool> values);
  void appendInt64Array(uint32_t entry, uint64_t timestamp_us, std::span<const int64_t> values);
  void appendDoubleArray(uint32_t entry, uint64_t timestamp_us, std::span<const double> values);
  void appendStringArray(uint32_t entry, uint64_t timestamp_us, std::span<const std::string> values);

  [[nodiscard]] const std::vector<uint8_t>& bytes() const { return bytes_; }
  // Writes bytes() to `path`; kCannotWrite when the file cannot be written.
  Result<Done, WpilogStatus> writeFile(const std::string& path) const;

 private:
  void record(uint32_t entry, uint64_t timestamp_us, std::span<const uint8_t> payload);

  std::vector<uint8_t> bytes_;
  uint32_t next_id_ = 1;
};

// Little-endian appends shared by the writer and the struct packers.
void putU32(std::vector<uint8_t>& out, uint32_t value);
void putF64(std::vector<uint8_t>& out, double value);

}  // namespace cyber::wpilog

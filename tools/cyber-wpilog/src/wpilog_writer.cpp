#include "cyber/wpilog/wpilog_writer.hpp"

#include <bit>
#include <cstring>
#include <fstream>

namespace cyber::wpilog {
namespace {

constexpr uint8_t kControlStart = 0;
constexpr uint8_t kControlFinish = 1;
constexpr uint8_t kControlSetMetadata = 2;

// Bytes needed for `value` in a variable-length little-endian header field (at least 1).
int widthOf(uint64_t value) {
  int n = 1;
  while (n < 8 && (value >> (8 * n)) != 0) ++n;
  return n;
}

void putLe(std::vector<uint8_t>& out, uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<uint8_t>(value >> (8 * i)));
}

void putString(std::vector<uint8_t>& out, std::string_view s) {
  putU32(out, static_cast<uint32_t>(s.size()));
  out.insert(out.end(), s.begin(), s.end());
}

std::span<const uint8_t> asBytes(std::string_view s) { return {reinterpret_cast<const uint8_t*>(s.data()), s.size()}; }

}  // namespace

void putU32(std::vector<uint8_t>& out, uint32_t value) { putLe(out, value, 4); }
void putF64(std::vector<uint8_t>& out, double value) { putLe(out, std::bit_cast<uint64_t>(value), 8); }

Writer::Writer(std::string_view extra_header) : bytes_{'W', 'P', 'I', 'L', 'O', 'G', 0x00, 0x01} {  // version 1.0
  putString(bytes_, extra_header);
}

void Writer::record(uint32_t entry, uint64_t timestamp_us, std::span<const uint8_t> payload) {
  const int id_bytes = std::min(4, widthOf(entry));
  const int size_bytes = std::min(4, widthOf(payload.size()));
  const int time_bytes = widthOf(timestamp_us);
  bytes_.push_back(static_cast<uint8_t>((id_bytes - 1) | ((size_bytes - 1) << 2) | ((time_bytes - 1) << 4)));
  putLe(bytes_, entry, id_bytes);
  putLe(bytes_, payload.size(), size_bytes);
  putLe(bytes_, timestamp_us, time_bytes);
  bytes_.insert(bytes_.end(), payload.begin(), payload.end());
}

uint32_t Writer::start(std::string_view name, std::string_view type, std::string_view metadata, uint64_t timestamp_us) {
  const uint32_t id = next_id_++;
  std::vector<uint8_t> payload{kControlStart};
  putU32(payload, id);
  putString(payload, name);
  putString(payload, type);
  putString(payload, metadata);
  record(0, timestamp_us, payload);
  return id;
}

void Writer::finish(uint32_t entry, uint64_t timestamp_us) {
  std::vector<uint8_t> payload{kControlFinish};
  putU32(payload, entry);
  record(0, timestamp_us, payload);
}

void Writer::setMetadata(uint32_t entry, std::string_view metadata, uint64_t timestamp_us) {
  std::vector<uint8_t> payload{kControlSetMetadata};
  putU32(payload, entry);
  putString(payload, metadata);
  record(0, timestamp_us, payload);
}

void Writer::addStructSchema(std::string_view struct_name, std::string_view schema, uint64_t timestamp_us) {
  const uint32_t id = start("/.schema/struct:" + std::string(struct_name), "structschema", "", timestamp_us);
  appendRaw(id, timestamp_us, asBytes(schema));
}

void Writer::appendRaw(uint32_t entry, uint64_t timestamp_us, std::span<const uint8_t> payload) {
  record(entry, timestamp_us, payload);
}

void Writer::appendBoolean(uint32_t entry, uint64_t timestamp_us, bool value) {
  const uint8_t b = value ? 1 : 0;
  record(entry, timestamp_us, {&b, 1});
}

void Writer::appendInt64(uint32_t entry, uint64_t timestamp_us, int64_t value) {
  std::vector<uint8_t> payload;
  putLe(payload, static_cast<uint64_t>(value), 8);
  record(entry, timestamp_us, payload);
}

void Writer::appendFloat(uint32_t entry, uint64_t timestamp_us, float value) {
  std::vector<uint8_t> payload;
  putLe(payload, std::bit_cast<uint32_t>(value), 4);
  record(entry, timestamp_us, payload);
}

void Writer::appendDouble(uint32_t entry, uint64_t timestamp_us, double value) {
  std::vector<uint8_t> payload;
  putF64(payload, value);
  record(entry, timestamp_us, payload);
}

void Writer::appendString(uint32_t entry, uint64_t timestamp_us, std::string_view value) {
  record(entry, timestamp_us, asBytes(value));
}

void Writer::appendBooleanArray(uint32_t entry, uint64_t timestamp_us, std::span<const bool> values) {
  std::vector<uint8_t> payload;
  for (bool v : values) payload.push_back(v ? 1 : 0);
  record(entry, timestamp_us, payload);
}

void Writer::appendInt64Array(uint32_t entry, uint64_t timestamp_us, std::span<const int64_t> values) {
  std::vector<uint8_t> payload;
  for (int64_t v : values) putLe(payload, static_cast<uint64_t>(v), 8);
  record(entry, timestamp_us, payload);
}

void Writer::appendDoubleArray(uint32_t entry, uint64_t timestamp_us, std::span<const double> values) {
  std::vector<uint8_t> payload;
  for (double v : values) putF64(payload, v);
  record(entry, timestamp_us, payload);
}

void Writer::appendStringArray(uint32_t entry, uint64_t timestamp_us, std::span<const std::string> values) {
  std::vector<uint8_t> payload;
  putU32(payload, static_cast<uint32_t>(values.size()));
  for (const std::string& v : values) putString(payload, v);
  record(entry, timestamp_us, payload);
}

Result<Done, WpilogStatus> Writer::writeFile(const std::string& path) const {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes_.data()), static_cast<std::streamsize>(bytes_.size()));
  out.close();
  if (!out) return Result<Done, WpilogStatus>::failure(WpilogStatus::kCannotWrite, path + ": cannot write");
  return Done{};
}

}  // namespace cyber::wpilog

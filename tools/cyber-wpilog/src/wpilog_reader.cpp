#include "cyber/wpilog/wpilog_reader.hpp"

#include <bit>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>

namespace cyber::wpilog {
namespace {

uint64_t getLe(const uint8_t* p, int bytes) {
  uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v |= static_cast<uint64_t>(p[i]) << (8 * i);
  return v;
}

// A bounds-checked cursor over a byte range.
struct Cursor {
  std::span<const uint8_t> data;
  size_t at = 0;
  [[nodiscard]] bool has(size_t n) const { return data.size() - at >= n; }
  bool le(int bytes, uint64_t* out) {
    if (!has(static_cast<size_t>(bytes))) return false;
    *out = getLe(data.data() + at, bytes);
    at += static_cast<size_t>(bytes);
    return true;
  }
  bool string(std::string* out) {
    uint64_t n = 0;
    if (!le(4, &n) || !has(n)) return false;
    out->assign(reinterpret_cast<const char*>(data.data() + at), n);
    at += n;
    return true;
  }
};

Error<WpilogStatus> failure(WpilogStatus status, std::string message) { return {status, std::move(message)}; }

template <typename T, typename Decode>
std::optional<std::vector<T>> fixedArray(std::span<const uint8_t> payload, size_t width, Decode decode) {
  if (payload.size() % width != 0) return std::nullopt;
  std::vector<T> out;
  out.reserve(payload.size() / width);
  for (size_t i = 0; i < payload.size(); i += width) out.push_back(decode(payload.subspan(i, width)));
  return out;
}

}  // namespace

std::optional<size_t> Log::find(std::string_view name) const {
  for (size_t i = 0; i < entries.size(); ++i) {
    if (entries[i].name == name) return i;
  }
  return std::nullopt;
}

std::vector<const Record*> Log::recordsOf(size_t index) const {
  std::vector<const Record*> out;
  for (const Record& r : records) {
    if (r.entry == index) out.push_back(&r);
  }
  return out;
}

Result<Log, WpilogStatus> parse(std::vector<uint8_t> bytes) {
  Log log;
  log.bytes = std::move(bytes);
  Cursor c{log.bytes};
  if (!c.has(6)) return failure(WpilogStatus::kTruncated, "shorter than the 12-byte header");
  if (std::memcmp(log.bytes.data(), "WPILOG", 6) != 0)
    return failure(WpilogStatus::kBadMagic, "does not start with WPILOG");
  c.at = 6;
  uint64_t version = 0;
  if (!c.le(2, &version)) return failure(WpilogStatus::kTruncated, "header ends in the version");
  log.version = static_cast<uint16_t>(version);
  if ((log.version >> 8) != 1) {
    return failure(WpilogStatus::kUnsupportedVersion, "version " + std::to_string(log.version >> 8) + "." +
                                                          std::to_string(log.version & 0xff) + " (only 1.x is known)");
  }
  if (!c.string(&log.extra_header)) return failure(WpilogStatus::kTruncated, "header ends in the extra header string");

  std::map<uint32_t, size_t> open;  // entry id -> index into log.entries
  while (c.at < log.bytes.size()) {
    const uint8_t lengths = log.bytes[c.at++];
    const int id_bytes = (lengths & 0x3) + 1;
    const int size_bytes = ((lengths >> 2) & 0x3) + 1;
    const int time_bytes = ((lengths >> 4) & 0x7) + 1;
    uint64_t id = 0, size = 0, timestamp = 0;
    if (!c.le(id_bytes, &id) || !c.le(size_bytes, &size) || !c.le(time_bytes, &timestamp) || !c.has(size)) {
      return failure(WpilogStatus::kTruncated, "the file ends inside a record");
    }
    const size_t payload_at = c.at;
    c.at += size;
    const std::span<const uint8_t> payload(log.bytes.data() + payload_at, size);
    if (id != 0) {
      const auto it = open.find(static_cast<uint32_t>(id));
      if (it == open.end()) {
        return failure(WpilogStatus::kUnknownEntry,
                       "record for entry " + std::to_string(id) + ", which is not started");
      }
      log.records.push_back(Record{it->second, timestamp, payload_at, size});
      continue;
    }
    Cursor p{payload};
    uint64_t control = 0, target = 0;
    auto bad = [&](const std::string& what) { return failure(WpilogStatus::kBadControlRecord, what); };
    if (!p.le(1, &control) || !p.le(4, &target)) return bad("control record shorter than 5 bytes");
    const uint32_t target_id = static_cast<uint32_t>(target);
    if (control == 0) {
      Entry e;
      e.id = target_id;
      e.start_timestamp_us = timestamp;
      if (!p.string(&e.name) || !p.string(&e.type) || !p.string(&e.metadata) || p.at != payload.size()) {
        return bad("malformed Start record");
      }
      if (target_id == 0) return bad("Start record for the control entry 0");
      open[target_id] = log.entries.size();
      log.entries.push_back(std::move(e));
    } else if (control == 1) {
      if (p.at != payload.size()) return bad("malformed Finish record");
      if (open.erase(target_id) == 0) {
        return failure(WpilogStatus::kUnknownEntry,
                       "Finish for entry " + std::to_string(target_id) + ", which is not started");
      }
    } else if (control == 2) {
      std::string metadata;
      if (!p.string(&metadata) || p.at != payload.size()) return bad("malformed Set Metadata record");
      const auto it = open.find(target_id);
      if (it == open.end()) {
        return failure(WpilogStatus::kUnknownEntry,
                       "Set Metadata for entry " + std::to_string(target_id) + ", which is not started");
      }
      log.entries[it->second].metadata = std::move(metadata);
    } else {
      return bad("unknown control record type " + std::to_string(control));
    }
  }
  return log;
}

Result<Log, WpilogStatus> readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return failure(WpilogStatus::kCannotOpen, path + ": cannot open");
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Result<Log, WpilogStatus> result = parse(std::move(bytes));
  if (!result) return failure(result.status(), path + ": " + result.error().message);
  return result;
}

std::optional<bool> asBoolean(std::span<const uint8_t> payload) {
  if (payload.size() != 1) return std::nullopt;
  return payload[0] != 0;
}

std::optional<int64_t> asInt64(std::span<const uint8_t> payload) {
  if (payload.size() != 8) return std::nullopt;
  return static_cast<int64_t>(getLe(payload.data(), 8));
}

std::optional<float> asFloat(std::span<const uint8_t> payload) {
  if (payload.size() != 4) return std::nullopt;
  return std::bit_cast<float>(static_cast<uint32_t>(getLe(payload.data(), 4)));
}

std::optional<double> asDouble(std::span<const uint8_t> payload) {
  if (payload.size() != 8) return std::nullopt;
  return std::bit_cast<double>(getLe(payload.data(), 8));
}

std::string asString(std::span<const uint8_t> payload) {
  return {reinterpret_cast<const char*>(payload.data()), payload.size()};
}

std::optional<std::vector<bool>> asBooleanArray(std::span<const uint8_t> payload) {
  return fixedArray<bool>(payload, 1, [](auto b) { return b[0] != 0; });
}

std::optional<std::vector<int64_t>> asInt64Array(std::span<const uint8_t> payload) {
  return fixedArray<int64_t>(payload, 8, [](auto b) { return *asInt64(b); });
}

std::optional<std::vector<float>> asFloatArray(std::span<const uint8_t> payload) {
  return fixedArray<float>(payload, 4, [](auto b) { return *asFloat(b); });
}

std::optional<std::vector<double>> asDoubleArray(std::span<const uint8_t> payload) {
  return fixedArray<double>(payload, 8, [](auto b) { return *asDouble(b); });
}

std::optional<std::vector<std::string>> asStringArray(std::span<const uint8_t> payload) {
  Cursor c{payload};
  uint64_t count = 0;
  if (!c.le(4, &count)) return std::nullopt;
  std::vector<std::string> out;
  for (uint64_t i = 0; i < count; ++i) {
    std::string s;
    if (!c.string(&s)) return std::nullopt;
    out.push_back(std::move(s));
  }
  if (c.at != payload.size()) return std::nullopt;
  return out;
}

bool decodesAs(std::string_view type, std::span<const uint8_t> payload) {
  if (type == "boolean") return asBoolean(payload).has_value();
  if (type == "int64") return asInt64(payload).has_value();
  if (type == "float") return asFloat(payload).has_value();
  if (type == "double") return asDouble(payload).has_value();
  if (type == "boolean[]") return asBooleanArray(payload).has_value();
  if (type == "int64[]") return asInt64Array(payload).has_value();
  if (type == "float[]") return asFloatArray(payload).has_value();
  if (type == "double[]") return asDoubleArray(payload).has_value();
  if (type == "string[]") return asStringArray(payload).has_value();
  return true;  // string, raw, json and other types carry any bytes
}

}  // namespace cyber::wpilog

#pragma once
// Reading the optional keys of [planner] and [daemon]: each key left out keeps the value its field
// already holds (a documented constant, or one derived from the robot), and every key's value and
// source are logged (docs/configuration.md, "Defaults").

#include <string>
#include <vector>

#include "cyber/config/setting_origin.hpp"
#include "cyber/planner.hpp"
#include "table_reader.hpp"

namespace cyber::config::detail {

class SettingReader {
 public:
  SettingReader(TableReader& table, std::vector<SettingOrigin>& log) : table_(table), log_(log) {}

  // `fallback` says where the field's current value came from when the key is left out.
  void number(const std::string& key, double& field, Bounds bounds, SettingSource fallback = SettingSource::kDefault);
  void integer(const std::string& key, int& field, long long min, long long max);
  void boolean(const std::string& key, bool& field);
  void string(const std::string& key, std::string& field);
  void jointVector(const std::string& key, planner::JointVector& field, Bounds bounds,
                   SettingSource fallback = SettingSource::kDefault);
  // Logs a value the caller read or derived itself.
  void log(const std::string& key, std::string value, SettingSource source);

  [[nodiscard]] TableReader& table() { return table_; }

 private:
  SettingSource sourceOf(const std::string& key, SettingSource fallback) const {
    return table_.has(key) ? SettingSource::kGiven : fallback;
  }

  TableReader& table_;
  std::vector<SettingOrigin>& log_;
};

}  // namespace cyber::config::detail

#include "setting_reader.hpp"

#include <fmt/format.h>

namespace cyber::config::detail {

void SettingReader::log(const std::string& key, std::string value, SettingSource source) {
  log_.push_back(SettingOrigin{table_.pathOf(key), std::move(value), source});
}

void SettingReader::number(const std::string& key, double& field, Bounds bounds, SettingSource fallback) {
  const SettingSource source = sourceOf(key, fallback);
  if (source == SettingSource::kGiven) field = table_.number(key, bounds);
  log(key, fmt::format("{}", field), source);
}

void SettingReader::integer(const std::string& key, int& field, long long min, long long max) {
  const SettingSource source = sourceOf(key, SettingSource::kDefault);
  if (source == SettingSource::kGiven) field = static_cast<int>(table_.integer(key, min, max));
  log(key, fmt::format("{}", field), source);
}

void SettingReader::boolean(const std::string& key, bool& field) {
  const SettingSource source = sourceOf(key, SettingSource::kDefault);
  if (source == SettingSource::kGiven) field = table_.boolean(key);
  log(key, field ? "true" : "false", source);
}

void SettingReader::string(const std::string& key, std::string& field) {
  const SettingSource source = sourceOf(key, SettingSource::kDefault);
  if (source == SettingSource::kGiven) field = table_.string(key);
  log(key, fmt::format("\"{}\"", field), source);
}

void SettingReader::jointVector(const std::string& key, planner::JointVector& field, Bounds bounds,
                                SettingSource fallback) {
  const SettingSource source = sourceOf(key, fallback);
  if (source == SettingSource::kGiven) field = table_.jointVector(key, static_cast<int>(field.size()), bounds);
  std::string text = "[";
  for (int j = 0; j < field.size(); ++j) text += fmt::format("{}{}", j == 0 ? "" : ", ", field[j]);
  log(key, text + "]", source);
}

}  // namespace cyber::config::detail

#pragma once
// Where each [planner] and [daemon] setting of a loaded description came from, so a tool can show
// which the file gave and which it left to the defaults (docs/configuration.md, "Defaults").

#include <string>

namespace cyber::config {

enum class SettingSource {
  kGiven,    // the file has the key
  kDerived,  // left out: derived from the robot (cyber/config/derived_defaults.hpp)
  kDefault,  // left out: the documented constant
};

inline const char* sourceName(SettingSource source) {
  switch (source) {
    case SettingSource::kGiven: return "given";
    case SettingSource::kDerived: return "derived";
    case SettingSource::kDefault: return "default";
  }
  return "?";
}

struct SettingOrigin {
  std::string key;    // the full key, e.g. "planner.grid.step"
  std::string value;  // as the file would write it, e.g. "[0.02, 0.02]"
  SettingSource source = SettingSource::kGiven;
};

}  // namespace cyber::config

#pragma once
// Loading the TOML robot description. Start-up only: errors are exceptions that name the key.

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cyber/config/daemon_settings.hpp"
#include "cyber/config/setting_origin.hpp"
#include "cyber/planner.hpp"

namespace cyber::config {

struct NamedPose {
  std::string name;
  planner::JointVector q;  // joint units, chain order
};

// The optional [poses.SET] tables: poses a team names for one set of held game pieces, SET "none"
// or piece names joined by '+' (docs/configuration.md), drawn by cyber-plot --config.
struct PoseSet {
  std::string name;  // as in the file
  planner::HeldPieces pieces;
  std::vector<NamedPose> poses;
};

struct Config {
  planner::RobotModel robot;
  DaemonSettings daemon;
  std::vector<PoseSet> poses;  // the sets the file has, by name
  // Every [planner] and [daemon] setting with its value and whether the file gave it or left it to
  // a default, derived or constant (docs/configuration.md, "Defaults"), in the order read.
  std::vector<SettingOrigin> settings;
};

// Thrown for any invalid configuration; what() reads "<source>: <key>: <problem>".
class ConfigError : public std::runtime_error {
 public:
  ConfigError(std::string key, const std::string& message) : std::runtime_error(message), key_(std::move(key)) {}
  [[nodiscard]] const std::string& key() const { return key_; }

 private:
  std::string key_;
};

// Parses TOML text; `source_name` only labels messages.
Config parseConfig(std::string_view toml_text, std::string_view source_name);
// Reads and parses a file.
Config loadConfigFile(const std::string& path);
// The default robot, compiled into the binary from config/reefscape-2025.toml.
std::string_view embeddedDefaultConfig();
std::string_view embeddedDefaultConfigName();
Config loadEmbeddedDefaultConfig();

}  // namespace cyber::config

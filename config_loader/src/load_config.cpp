#include "cyber/config/load_config.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "read_chain.hpp"
#include "read_daemon.hpp"
#include "read_drives.hpp"
#include "read_planner.hpp"
#include "table_reader.hpp"

namespace cyber::config {
namespace {

using detail::Bounds;
using detail::TableReader;
using planner::RobotModel;

Config readRoot(const toml::table& root_table) {
  Config config;
  RobotModel& robot = config.robot;
  TableReader root(root_table, "");
  detail::rejectOldFormat(root);
  robot.name = root.string("name");
  robot.clearance_m = root.number("clearance_m", Bounds{0.0, 1.0});
  detail::readJoints(root, robot);
  detail::readLinks(root.table("links"), robot);
  if (root.has("pieces")) detail::readPieces(root.table("pieces"), robot);
  detail::readScenes(root, root.table("obstacles"), robot);
  detail::readDrives(root.table("motors"), root.table("drives"), robot);
  detail::readPlanner(root.optionalTable("planner"), robot, config.settings);
  config.daemon = detail::readDaemon(root.optionalTable("daemon"), robot, config.settings);
  if (root.has("poses")) config.poses = detail::readPoses(root.table("poses"), robot);
  root.finish();
  return config;
}

}  // namespace

Config parseConfig(std::string_view toml_text, std::string_view source_name) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source_name);
  } catch (const toml::parse_error& e) {
    throw ConfigError(
        "", fmt::format("{}:{}:{}: {}", source_name, e.source().begin.line, e.source().begin.column, e.description()));
  }
  try {
    return readRoot(root);
  } catch (const ConfigError& e) {
    throw ConfigError(e.key(), std::string(source_name) + ": " + e.what());
  }
}

Config loadConfigFile(const std::string& path) {
  errno = 0;
  std::ifstream in(path);
  if (!in) throw ConfigError("", path + ": cannot open the configuration file (" + std::strerror(errno) + ")");
  // A directory opens but reads as empty, which would be reported as a missing key.
  if (std::filesystem::is_directory(path)) throw ConfigError("", path + ": is a directory, not a configuration file");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return parseConfig(text, path);
}

Config loadEmbeddedDefaultConfig() { return parseConfig(embeddedDefaultConfig(), embeddedDefaultConfigName()); }

}  // namespace cyber::config

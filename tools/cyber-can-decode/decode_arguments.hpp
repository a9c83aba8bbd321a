#pragma once
// The command line of cyber-can-decode (usage in decodeUsage()).

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cyber/cli/argument_status.hpp"
#include "cyber/planner.hpp"
#include "decoded_line.hpp"

namespace cyber::tools {

struct DecodeArguments {
  OutputFormat format = OutputFormat::kText;
  bool strict = false;
  std::optional<std::string> config_path;                                // absent: the embedded reference config
  std::array<std::optional<std::uint8_t>, planner::kMaxJoints> devices;  // --joint0-device ... --joint2-device
  std::optional<std::string> path;                                       // absent or "-": stdin
  bool help = false;
};

Result<DecodeArguments, cli::ArgumentStatus> parseDecodeArguments(const std::vector<std::string>& args);

// The joints' devices, names and units: the config's (--config, else the embedded reference
// config), device numbers overridden by --joint0-device / --joint1-device. Throws on a config
// that does not load.
JointDevices jointDevices(const DecodeArguments& args);

const char* decodeUsage();

}  // namespace cyber::tools

#pragma once
// The command line of cyber-can-decode (usage in decodeUsage()).

#include <optional>
#include <string>
#include <vector>

#include "cyber/cli/parsed.hpp"
#include "decoded_line.hpp"

namespace cyber::tools {

struct DecodeArguments {
  OutputFormat format = OutputFormat::kText;
  bool strict = false;
  JointDevices joints;
  std::optional<std::string> path;  // absent or "-": stdin
  bool help = false;
};

cli::Parsed<DecodeArguments> parseDecodeArguments(const std::vector<std::string>& args);

const char* decodeUsage();

}  // namespace cyber::tools

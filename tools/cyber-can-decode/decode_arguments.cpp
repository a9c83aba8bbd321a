#include "decode_arguments.hpp"

#include "cyber/can/frc_id.hpp"
#include "cyber/cli/argument_parser.hpp"
#include "cyber/cli/number_text.hpp"
#include "cyber/config/load_config.hpp"
#include "cyber/planner.hpp"

namespace cyber::tools {

namespace {

cli::ValueHandler device(std::optional<std::uint8_t>* into) {
  return [into](const std::string& text) -> std::string {
    const auto value = cli::parseInteger(text);
    if (!value || *value < 0 || *value > can::kMaxDeviceNumber) return "must be 0..63, got '" + text + "'";
    *into = static_cast<std::uint8_t>(*value);
    return "";
  };
}

}  // namespace

const char* decodeUsage() {
  return "usage: cyber-can-decode [--csv] [--strict] [--config FILE] [--joint0-device N] [--joint1-device N]\n"
         "                       [--joint2-device N]\n"
         "                        [FILE|-]\n"
         "  Decodes a candump -L log (FILE, or stdin when FILE is - or absent).\n"
         "  --csv               one CSV row per frame instead of text\n"
         "  --strict            exit 1 if a frame is undecodable or a line is malformed\n"
         "  --config FILE       robot description: the joints' device numbers ([daemon.devices]), names\n"
         "                      and units ([[joints]]) (default: the embedded config/reefscape-2025.toml)\n"
         "  --joint0-device N   device number of joint 0 (default: the config's; 1 for the elevator)\n"
         "  --joint1-device N   device number of joint 1 (default: the config's; 2 for the arm)\n"
         "  --joint2-device N   device number of joint 2 of a three-joint chain (default: the config's)\n";
}

Result<DecodeArguments, cli::ArgumentStatus> parseDecodeArguments(const std::vector<std::string>& args) {
  DecodeArguments out;
  cli::ArgumentParser parser;
  parser.flag("--csv", [&] { out.format = OutputFormat::kCsv; });
  parser.flag("--strict", [&] { out.strict = true; });
  parser.option("--config", cli::store(out.config_path));
  parser.option("--joint0-device", device(&out.devices[0]));
  parser.option("--joint1-device", device(&out.devices[1]));
  parser.option("--joint2-device", device(&out.devices[2]));
  parser.positional([&](const std::string& path) -> std::string {
    if (out.path) return "more than one input file";
    out.path = path;
    return "";
  });
  if (auto decided = parser.parseInto(args, out)) return *decided;
  return out;
}

JointDevices jointDevices(const DecodeArguments& args) {
  const config::Config config =
      args.config_path ? config::loadConfigFile(*args.config_path) : config::loadEmbeddedDefaultConfig();
  JointDevices joints{{}, {}, {}};
  for (int j = 0; j < config.robot.jointCount(); ++j) {
    const auto index = static_cast<size_t>(j);
    joints.devices.push_back(
        args.devices[index].value_or(static_cast<std::uint8_t>(config.daemon.devices.joints[index])));
    joints.names.push_back(config.robot.joints[j].name);
    joints.units.push_back(planner::unitName(config.robot.joints[j].type));
  }
  return joints;
}

}  // namespace cyber::tools

#include "decode_arguments.hpp"

#include "cyber/can/frc_id.hpp"
#include "cyber/cli/argument_parser.hpp"
#include "cyber/cli/number_text.hpp"

namespace cyber::tools {

namespace {

cli::ValueHandler device(std::uint8_t* into) {
  return [into](const std::string& text) -> std::string {
    const auto value = cli::parseInteger(text);
    if (!value || *value < 0 || *value > can::kMaxDeviceNumber) return "must be 0..63, got '" + text + "'";
    *into = static_cast<std::uint8_t>(*value);
    return "";
  };
}

}  // namespace

const char* decodeUsage() {
  return "usage: cyber-can-decode [--csv] [--strict] [--elevator-device N] [--arm-device N] [FILE|-]\n"
         "  Decodes a candump -L log (FILE, or stdin when FILE is - or absent).\n"
         "  --csv               one CSV row per frame instead of text\n"
         "  --strict            exit 1 if a frame is undecodable or a line is malformed\n"
         "  --elevator-device N device number of the elevator (default 1)\n"
         "  --arm-device N      device number of the arm (default 2)\n";
}

cli::Parsed<DecodeArguments> parseDecodeArguments(const std::vector<std::string>& args) {
  DecodeArguments out;
  cli::ArgumentParser parser;
  parser.flag("--csv", [&] { out.format = OutputFormat::kCsv; });
  parser.flag("--strict", [&] { out.strict = true; });
  parser.option("--elevator-device", device(&out.joints.elevator));
  parser.option("--arm-device", device(&out.joints.arm));
  parser.positional([&](const std::string& path) -> std::string {
    if (out.path) return "more than one input file";
    out.path = path;
    return "";
  });
  if (auto decided = parser.parseInto(args, out)) return *decided;
  return out;
}

}  // namespace cyber::tools

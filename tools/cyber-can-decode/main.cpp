// cyber-can-decode [--csv] [--strict] [--elevator-device N] [--arm-device N] [FILE|-]
// Reads a candump -L log (FILE or stdin), prints each frame decoded per docs/can-protocol.md,
// and a summary on stderr. Exit 0 when the input was read (1 with --strict if any frame was
// undecodable or any line malformed), 2 on bad usage or an unreadable file.

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>

#include "cyber/can/frc_id.hpp"
#include "decoded_line.hpp"

namespace {

constexpr const char* kUsage =
    "usage: cyber-can-decode [--csv] [--strict] [--elevator-device N] [--arm-device N] [FILE|-]\n"
    "  Decodes a candump -L log (FILE, or stdin when FILE is - or absent).\n"
    "  --csv               one CSV row per frame instead of text\n"
    "  --strict            exit 1 if a frame is undecodable or a line is malformed\n"
    "  --elevator-device N device number of the elevator (default 1)\n"
    "  --arm-device N      device number of the arm (default 2)\n";

int usageError(const std::string& message) {
  std::cerr << "cyber-can-decode: " << message << "\n" << kUsage;
  return 2;
}

std::optional<std::uint8_t> parseDevice(std::string_view text) {
  if (text.empty() || text.size() > 2) return std::nullopt;
  int value = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + (c - '0');
  }
  if (value > cyber::can::kMaxDeviceNumber) return std::nullopt;
  return static_cast<std::uint8_t>(value);
}

}  // namespace

int main(int argc, char** argv) {
  using cyber::tools::OutputFormat;
  OutputFormat format = OutputFormat::kText;
  bool strict = false;
  cyber::tools::JointDevices joints;
  std::optional<std::string> path;

  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      return 0;
    }
    if (arg == "--csv") {
      format = OutputFormat::kCsv;
    } else if (arg == "--strict") {
      strict = true;
    } else if (arg == "--elevator-device" || arg == "--arm-device") {
      if (i + 1 >= argc) return usageError(std::string(arg) + " needs a device number");
      const auto device = parseDevice(argv[++i]);
      if (!device) return usageError(std::string(arg) + " must be 0..63, got '" + argv[i] + "'");
      (arg == "--arm-device" ? joints.arm : joints.elevator) = *device;
    } else if (arg.size() > 1 && arg[0] == '-') {
      return usageError("unknown option '" + std::string(arg) + "'");
    } else if (path) {
      return usageError("more than one input file");
    } else {
      path = std::string(arg);
    }
  }

  std::ifstream file;
  std::istream* input = &std::cin;
  if (path && *path != "-") {
    file.open(*path);
    if (!file) return usageError("cannot open '" + *path + "'");
    input = &file;
  }

  cyber::tools::DecodeCounts counts;
  if (format == OutputFormat::kCsv) std::cout << cyber::tools::csvHeader() << '\n';
  std::string line;
  long line_number = 0;
  while (std::getline(*input, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank line
    const auto record = cyber::can::parseLogLine(line);
    if (!record) {
      ++counts.malformed;
      std::cerr << "line " << line_number << ": malformed: " << record.error().reason << '\n';
      continue;
    }
    std::cout << cyber::tools::decodeRecord(record.value(), joints, format, counts) << '\n';
  }

  std::cerr << "cyber-can-decode: " << counts.frames << " frames (" << counts.decoded
            << " decoded, " << counts.undecodable << " undecodable, " << counts.other
            << " other), " << counts.malformed << " malformed lines\n";
  if (strict && (counts.undecodable > 0 || counts.malformed > 0)) return 1;
  return 0;
}

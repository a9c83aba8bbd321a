// cyber-can-decode [--csv] [--strict] [--config FILE] [--joint0-device N] [--joint1-device N] [FILE|-]
// Reads a candump -L log (FILE or stdin), prints each frame decoded per docs/can-protocol.md,
// and a summary on stderr. Exit 0 when the input was read (1 with --strict if any frame was
// undecodable or any line malformed), 2 on bad usage or an unreadable file.

#include <exception>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "cyber/cli/usage_exit.hpp"
#include "decode_arguments.hpp"

int main(int argc, char** argv) {
  const auto parsed = cyber::tools::parseDecodeArguments(std::vector<std::string>(argv + 1, argv + argc));
  const cyber::cli::ProgramUsage program{"cyber-can-decode", cyber::tools::decodeUsage(), true};
  if (const auto status = cyber::cli::exitBeforeWork(parsed, program)) return *status;
  const cyber::tools::DecodeArguments& args = parsed.value();
  const auto& path = args.path;
  cyber::tools::JointDevices joints;
  try {
    joints = cyber::tools::jointDevices(args);
  } catch (const std::exception& error) {
    std::cerr << "cyber-can-decode: " << error.what() << "\n";
    return 2;
  }

  std::ifstream file;
  std::istream* input = &std::cin;
  if (path && *path != "-") {
    file.open(*path);
    if (!file) return cyber::cli::reportBadUsage(program, cyber::cli::badUsage("cannot open '" + *path + "'"));
    input = &file;
  }

  cyber::tools::DecodeCounts counts;
  if (args.format == cyber::tools::OutputFormat::kCsv) std::cout << cyber::tools::csvHeader() << '\n';
  std::string line;
  long line_number = 0;
  while (std::getline(*input, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank line
    const auto record = cyber::can::parseLogLine(line);
    if (!record) {
      ++counts.malformed;
      std::cerr << "line " << line_number << ": malformed: " << record.error().message << '\n';
      continue;
    }
    std::cout << cyber::tools::decodeRecord(record.value(), joints, args.format, counts) << '\n';
  }

  std::cerr << "cyber-can-decode: " << counts.frames << " frames (" << counts.decoded << " decoded, "
            << counts.undecodable << " undecodable, " << counts.other << " other), " << counts.malformed
            << " malformed lines\n";
  if (args.strict && (counts.undecodable > 0 || counts.malformed > 0)) return 1;
  return 0;
}

#pragma once
// What every program's main does first with its parsed command line (docs/design.md,
// "Command-line contracts"): --help prints the usage on stdout and exits 0; a bad command line is
// "PROGRAM: reason" on stderr (then the usage, for the programs that show it) and kExitBadUsage.

#include <optional>
#include <string>

#include "cyber/cli/argument_status.hpp"

namespace cyber::cli {

struct ProgramUsage {
  std::string program;  // prefixes the error line
  std::string usage;
  bool usage_on_error = false;  // also print the usage after the error line
};

int printUsage(const ProgramUsage& program);                                          // 0
int reportBadUsage(const ProgramUsage& program, const Error<ArgumentStatus>& error);  // kExitBadUsage

// The exit status when the command line ends the program before its work; nothing: go on.
template <class Arguments>
[[nodiscard]] std::optional<int> exitBeforeWork(const Result<Arguments, ArgumentStatus>& parsed,
                                                const ProgramUsage& program) {
  if (!parsed) return reportBadUsage(program, parsed.error());
  if (parsed.value().help) return printUsage(program);
  return std::nullopt;
}

}  // namespace cyber::cli

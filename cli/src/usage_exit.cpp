#include "cyber/cli/usage_exit.hpp"

#include <cstdio>

namespace cyber::cli {

int printUsage(const ProgramUsage& program) {
  std::fputs(program.usage.c_str(), stdout);
  return 0;
}

int reportBadUsage(const ProgramUsage& program, const Error<ArgumentStatus>& error) {
  std::fprintf(stderr, "%s: %s\n", program.program.c_str(), error.message.c_str());
  if (program.usage_on_error) std::fputs(program.usage.c_str(), stderr);
  return kExitBadUsage;
}

}  // namespace cyber::cli

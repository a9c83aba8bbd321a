#pragma once
// Runs a built command-line tool from a test and captures what it printed and its exit code.

#include <string>

namespace cyber::test {

struct ToolRun {
  int exit_code = -1;  // -1 when the tool could not be started or was killed by a signal
  std::string out;
  std::string err;
};

// `program` is the tool's path; `args` is a shell command tail (arguments and redirections).
ToolRun runTool(const std::string& program, const std::string& args);

// The whole content of a file ("" when it cannot be read).
std::string readFile(const std::string& path);

}  // namespace cyber::test

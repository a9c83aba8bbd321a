#include "tool_run.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>

namespace cyber::test {

std::string readFile(const std::string& path) {
  std::ifstream file(path);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

ToolRun runTool(const std::string& program, const std::string& args) {
  // Per process and call, so tests of one binary running in parallel do not share the file.
  static int calls = 0;
  const std::string err_path =
      ::testing::TempDir() + "cyber_tool_" + std::to_string(::getpid()) + "_" + std::to_string(calls++) + "_stderr.txt";
  const std::string command = program + " " + args + " 2>" + err_path;
  ToolRun run;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return run;
  char buffer[4096];
  size_t got;
  while ((got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) run.out.append(buffer, got);
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.err = readFile(err_path);
  std::remove(err_path.c_str());
  return run;
}

}  // namespace cyber::test

// The shared start of every program: ArgumentParser::parseInto and cli::exitBeforeWork
// (cli/include/cyber/cli/usage_exit.hpp, docs/design.md "Command-line contracts").

#include "cyber/cli/usage_exit.hpp"

#include <gtest/gtest.h>

#include "cyber/cli/argument_parser.hpp"

namespace cyber::cli {
namespace {

struct Line {
  std::string name;
  bool help = false;
};

std::optional<Result<Line, ArgumentStatus>> decided(const std::vector<std::string>& args, Line& out) {
  ArgumentParser parser;
  parser.option("--name", store(out.name));
  return parser.parseInto(args, out);
}

TEST(ParseInto, LeavesAWholeLineToTheProgramsOwnChecks) {
  Line out;
  EXPECT_FALSE(decided({"--name", "x"}, out).has_value());
  EXPECT_EQ(out.name, "x");
  EXPECT_FALSE(out.help);
}

TEST(ParseInto, ReturnsTheArgumentsWithHelpSetOnHelp) {
  for (const char* help : {"--help", "-h"}) {
    Line out;
    const auto result = decided({"--name", "x", help, "--unknown"}, out);
    ASSERT_TRUE(result.has_value());
    ASSERT_TRUE(result->ok()) << help;
    EXPECT_TRUE(result->value().help);
    EXPECT_EQ(result->value().name, "x");
  }
}

TEST(ParseInto, ReturnsTheErrorOfABadLine) {
  Line out;
  const auto result = decided({"--unknown"}, out);
  ASSERT_TRUE(result.has_value());
  ASSERT_FALSE(result->ok());
  EXPECT_NE(result->error().message.find("--unknown"), std::string::npos) << result->error().message;
}

const ProgramUsage kQuiet{"prog", "usage: prog\n", false};
const ProgramUsage kShowsUsage{"prog", "usage: prog\n", true};

TEST(ExitBeforeWork, GoesOnWithAWholeLine) {
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  EXPECT_EQ(exitBeforeWork(Result<Line, ArgumentStatus>(Line{"x", false}), kShowsUsage), std::nullopt);
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(ExitBeforeWork, PrintsTheUsageOnStdoutAndExitsZeroOnHelp) {
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  EXPECT_EQ(exitBeforeWork(Result<Line, ArgumentStatus>(Line{"", true}), kQuiet), 0);
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "usage: prog\n");
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(ExitBeforeWork, NamesTheProgramOnStderrAndExitsTwoOnABadLine) {
  for (const ProgramUsage* program : {&kQuiet, &kShowsUsage}) {
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    EXPECT_EQ(exitBeforeWork(Result<Line, ArgumentStatus>(badUsage("--x: no")), *program), kExitBadUsage);
    EXPECT_EQ(kExitBadUsage, 2);
    EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
    EXPECT_EQ(testing::internal::GetCapturedStderr(),
              std::string("prog: --x: no\n") + (program->usage_on_error ? "usage: prog\n" : ""));
  }
}

}  // namespace
}  // namespace cyber::cli

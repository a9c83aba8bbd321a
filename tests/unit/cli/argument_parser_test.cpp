// The one option syntax every program shares (cli/include/cyber/cli/argument_parser.hpp).

#include "cyber/cli/argument_parser.hpp"

#include <gtest/gtest.h>

namespace cyber::cli {
namespace {

struct Seen {
  std::string name;
  bool verbose = false;
  std::vector<std::string> files;
};

Result<Scan, ArgumentStatus> parseInto(Seen& seen, const std::vector<std::string>& args) {
  ArgumentParser parser;
  parser.option("--name", [&](const std::string& v) -> std::string {
    if (v == "bad") return "refuses 'bad'";
    seen.name = v;
    return "";
  });
  parser.flag("--verbose", [&] { seen.verbose = true; });
  parser.positional([&](const std::string& f) {
    seen.files.push_back(f);
    return std::string();
  });
  return parser.parse(args);
}

std::string errorOf(const std::vector<std::string>& args) {
  Seen seen;
  const auto scan = parseInto(seen, args);
  EXPECT_EQ(scan.status(), ArgumentStatus::kBadUsage);
  return scan.ok() ? "" : scan.error().message;
}

TEST(ArgumentParser, SeparateAndJoinedValuesMeanTheSame) {
  for (const auto& args : {std::vector<std::string>{"--name", "-0.2,1", "--verbose", "a", "-"},
                           std::vector<std::string>{"--name=-0.2,1", "--verbose", "a", "-"}}) {
    Seen seen;
    const auto scan = parseInto(seen, args);
    ASSERT_TRUE(scan.ok()) << scan.error().message;
    EXPECT_EQ(scan.value(), Scan::kComplete);
    EXPECT_EQ(seen.name, "-0.2,1");
    EXPECT_TRUE(seen.verbose);
    EXPECT_EQ(seen.files, (std::vector<std::string>{"a", "-"}));
  }
  Seen seen;
  ASSERT_TRUE(parseInto(seen, {"--name=a=b"}).ok());
  EXPECT_EQ(seen.name, "a=b");  // only the first '=' splits
}

TEST(ArgumentParser, BadInputIsNamed) {
  EXPECT_EQ(errorOf({"--fast"}), "unknown argument '--fast' (see --help)");
  EXPECT_EQ(errorOf({"--fast=1"}), "unknown argument '--fast=1' (see --help)");
  EXPECT_EQ(errorOf({"--name"}), "--name needs a value");
  EXPECT_EQ(errorOf({"--name="}), "--name needs a value");
  EXPECT_EQ(errorOf({"--name", ""}), "--name needs a value");
  EXPECT_EQ(errorOf({"--verbose=yes"}), "--verbose takes no value, got '--verbose=yes'");
  EXPECT_EQ(errorOf({"--name=bad"}), "--name refuses 'bad'");
  EXPECT_EQ(errorOf({"--nam", "x"}), "unknown argument '--nam' (see --help)");  // no prefix matching
}

TEST(ArgumentParser, HelpStopsTheScan) {
  Seen seen;
  const auto scan = parseInto(seen, {"--verbose", "-h", "--fast"});
  ASSERT_TRUE(scan.ok());
  EXPECT_EQ(scan.value(), Scan::kHelp);
  ASSERT_TRUE(parseInto(seen, {"--help"}).ok());
}

TEST(ArgumentParser, WithoutAPositionalHandlerBareArgumentsAreErrors) {
  ArgumentParser parser;
  const auto scan = parser.parse({"file"});
  ASSERT_FALSE(scan.ok());
  EXPECT_EQ(scan.error().message, "unexpected argument 'file' (see --help)");
}

}  // namespace
}  // namespace cyber::cli

#include "cyber/daemon/io/command_line.hpp"

#include <gtest/gtest.h>

namespace cyber::daemon::io {
namespace {

TEST(CommandLine, ParsesEveryOption) {
  for (const auto& args : {std::vector<std::string>{"--config", "robot.toml", "--can", "none", "--lcm-url", "memq://"},
                           std::vector<std::string>{"--config=robot.toml", "--can=none", "--lcm-url=memq://"}}) {
    auto parsed = parseCommandLine(args);
    ASSERT_TRUE(parsed.ok()) << parsed.error().message;
    const auto& line = parsed.value();
    EXPECT_EQ(line.config_path, "robot.toml");
    EXPECT_EQ(line.can_interface, "none");
    EXPECT_EQ(line.lcm_url, "memq://");
    EXPECT_FALSE(line.help);
  }
}

TEST(CommandLine, ConfigIsOptionalAndUnknownArgumentsAreNamed) {
  // No --config: an empty path, which main() reads as the embedded default configuration.
  auto defaulted = parseCommandLine({"--can", "vcan0"});
  ASSERT_TRUE(defaulted.ok());
  EXPECT_EQ(defaulted.value().config_path, "");
  auto unknown = parseCommandLine({"--config", "a.toml", "--fast"});
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.error().message, "unknown argument '--fast' (see --help)");
  for (const auto& args : {std::vector<std::string>{"--config"}, std::vector<std::string>{"--config="},
                           std::vector<std::string>{"--config", ""}}) {
    auto no_value = parseCommandLine(args);
    ASSERT_FALSE(no_value.ok());
    EXPECT_EQ(no_value.error().message, "--config needs a value");
  }
}

TEST(CommandLine, HelpWinsOverEverythingElse) {
  auto parsed = parseCommandLine({"--help"});
  ASSERT_TRUE(parsed.ok());
  EXPECT_TRUE(parsed.value().help);
  EXPECT_NE(usage().find("--can IFACE|none"), std::string::npos);
}

}  // namespace
}  // namespace cyber::daemon::io

#include "cyber/daemon/io/command_line.hpp"

#include <gtest/gtest.h>

namespace cyber::daemon::io {
namespace {

TEST(CommandLine, ParsesEveryOption) {
  auto parsed = parseCommandLine({"--config", "robot.toml", "--can", "none", "--lcm-url", "memq://"});
  ASSERT_TRUE(std::holds_alternative<CommandLine>(parsed));
  const auto& line = std::get<CommandLine>(parsed);
  EXPECT_EQ(line.config_path, "robot.toml");
  EXPECT_EQ(line.can_interface, "none");
  EXPECT_EQ(line.lcm_url, "memq://");
  EXPECT_FALSE(line.help);
}

TEST(CommandLine, ConfigIsOptionalAndUnknownArgumentsAreNamed) {
  // No --config: an empty path, which main() reads as the embedded default configuration.
  auto defaulted = parseCommandLine({"--can", "vcan0"});
  ASSERT_TRUE(std::holds_alternative<CommandLine>(defaulted));
  EXPECT_EQ(std::get<CommandLine>(defaulted).config_path, "");
  auto unknown = parseCommandLine({"--config", "a.toml", "--fast"});
  ASSERT_TRUE(std::holds_alternative<CommandLineError>(unknown));
  EXPECT_EQ(std::get<CommandLineError>(unknown).message, "unknown argument '--fast'");
  auto no_value = parseCommandLine({"--config"});
  ASSERT_TRUE(std::holds_alternative<CommandLineError>(no_value));
  EXPECT_EQ(std::get<CommandLineError>(no_value).message, "--config needs a value");
}

TEST(CommandLine, HelpWinsOverEverythingElse) {
  auto parsed = parseCommandLine({"--help"});
  ASSERT_TRUE(std::holds_alternative<CommandLine>(parsed));
  EXPECT_TRUE(std::get<CommandLine>(parsed).help);
  EXPECT_NE(usage().find("--can IFACE|none"), std::string::npos);
}

}  // namespace
}  // namespace cyber::daemon::io

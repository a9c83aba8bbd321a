// cyber-robot's command line (tools/cyber-robot/robot_arguments.hpp).

#include "robot_arguments.hpp"

#include <gtest/gtest.h>

namespace cyber::tools {
namespace {

TEST(RobotArguments, CheckTakesOneDescriptionAndAnOptionalPicture) {
  const auto plain = parseRobotArguments({"check", "robot.toml"});
  ASSERT_TRUE(plain.ok());
  EXPECT_EQ(plain.value().command, "check");
  EXPECT_EQ(plain.value().config_path, "robot.toml");
  EXPECT_TRUE(plain.value().png_path.empty());
  const auto png = parseRobotArguments({"check", "--png=out.png", "robot.toml"});
  ASSERT_TRUE(png.ok());
  EXPECT_EQ(png.value().png_path, "out.png");
}

TEST(RobotArguments, BadLinesAreUsageErrorsThatSayWhy) {
  const auto message = [](const std::vector<std::string>& args) {
    const auto parsed = parseRobotArguments(args);
    EXPECT_FALSE(parsed.ok());
    return parsed ? std::string() : parsed.error().message;
  };
  EXPECT_NE(message({}).find("missing the command"), std::string::npos);
  EXPECT_NE(message({"verify", "robot.toml"}).find("unknown command 'verify'"), std::string::npos);
  EXPECT_NE(message({"check"}).find("one robot description"), std::string::npos);
  EXPECT_NE(message({"check", "a.toml", "b.toml"}).find("one robot description"), std::string::npos);
  EXPECT_NE(message({"check", "a.toml", "--png"}).find("--png"), std::string::npos);
}

TEST(RobotArguments, HelpStopsTheScan) {
  const auto parsed = parseRobotArguments({"--help"});
  ASSERT_TRUE(parsed.ok());
  EXPECT_TRUE(parsed.value().help);
}

}  // namespace
}  // namespace cyber::tools

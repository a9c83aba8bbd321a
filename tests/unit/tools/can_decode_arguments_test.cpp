// cyber-can-decode's command line (tools/cyber-can-decode/decode_arguments.cpp).

#include "decode_arguments.hpp"

#include "tool_arguments_test.hpp"

namespace cyber::tools {
namespace {

auto parse = [](const std::vector<std::string>& args) { return parseDecodeArguments(args); };

TEST(DecodeArguments, BothSpellingsOfAValueMeanTheSame) {
  for (const auto& args : {std::vector<std::string>{"--csv", "--elevator-device", "5", "--arm-device", "63", "log.txt"},
                           std::vector<std::string>{"--csv", "--elevator-device=5", "--arm-device=63", "log.txt"}}) {
    const DecodeArguments a = parsedOk(parse, args);
    EXPECT_EQ(a.format, OutputFormat::kCsv);
    EXPECT_EQ(a.joints.elevator, 5);
    EXPECT_EQ(a.joints.arm, 63);
    EXPECT_EQ(a.path, "log.txt");
  }
  EXPECT_EQ(parsedOk(parse, {"-"}).path, "-");
  EXPECT_FALSE(parsedOk(parse, {}).path);
}

TEST(DecodeArguments, BadInputIsNamed) {
  EXPECT_EQ(parseError(parse, {"--fast"}), "unknown argument '--fast' (see --help)");
  EXPECT_EQ(parseError(parse, {"--arm-device"}), "--arm-device needs a value");
  EXPECT_EQ(parseError(parse, {"--arm-device="}), "--arm-device needs a value");
  EXPECT_EQ(parseError(parse, {"--arm-device=64"}), "--arm-device must be 0..63, got '64'");
  EXPECT_EQ(parseError(parse, {"--elevator-device", "-1"}), "--elevator-device must be 0..63, got '-1'");
  EXPECT_EQ(parseError(parse, {"--strict=1"}), "--strict takes no value, got '--strict=1'");
  EXPECT_EQ(parseError(parse, {"a.log", "b.log"}), "more than one input file");
}

}  // namespace
}  // namespace cyber::tools

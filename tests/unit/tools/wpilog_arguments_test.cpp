// cyber-wpilog's command line (tools/cyber-wpilog/wpilog_arguments.cpp).

#include "wpilog_arguments.hpp"

#include "tool_arguments_test.hpp"

namespace cyber::tools {
namespace {

auto parse = [](const std::vector<std::string>& args) { return parseWpilogArguments(args); };

TEST(WpilogArguments, BothSpellingsOfAValueMeanTheSame) {
  for (const auto& args : {std::vector<std::string>{"--config", "r.toml", "in.lcmlog", "out.wpilog"},
                           std::vector<std::string>{"in.lcmlog", "--config=r.toml", "out.wpilog"}}) {
    const WpilogArguments a = parsedOk(parse, args);
    EXPECT_EQ(a.config_path, "r.toml");
    EXPECT_EQ(a.lcm_log_path, "in.lcmlog");
    EXPECT_EQ(a.wpilog_path, "out.wpilog");
  }
  EXPECT_EQ(parsedOk(parse, {"--list=x.wpilog"}).list_path, "x.wpilog");
}

TEST(WpilogArguments, BadInputIsNamed) {
  EXPECT_EQ(parseError(parse, {"--fast", "a", "b"}), "unknown argument '--fast' (see --help)");
  EXPECT_EQ(parseError(parse, {"--list"}), "--list needs a value");
  EXPECT_EQ(parseError(parse, {"--config=", "a", "b"}), "--config needs a value");
  EXPECT_EQ(parseError(parse, {"--list", "x.wpilog", "a"}), "--list takes no other files");
  EXPECT_EQ(parseError(parse, {"a"}), "expected IN.lcmlog OUT.wpilog (see --help)");
}

}  // namespace
}  // namespace cyber::tools

// cyber-plot's command line (tools/cyber-plot/plot_arguments.cpp).

#include "plot_arguments.hpp"

#include "tool_arguments_test.hpp"

namespace cyber::tools {
namespace {

auto parse = [](const std::vector<std::string>& args) { return parsePlotArguments(args); };

TEST(PlotArguments, BothSpellingsOfAValueMeanTheSame) {
  for (const auto& args : {std::vector<std::string>{"--world", "--at", "-0.2,1", "--scene", "open", "--out", "w.png"},
                           std::vector<std::string>{"--world", "--at=-0.2,1", "--scene=open", "--out=w.png"}}) {
    const PlotArguments a = parsedOk(parse, args);
    ASSERT_TRUE(a.at);
    EXPECT_EQ(*a.at, (planner::JointVector{{-0.2, 1.0}}));
    EXPECT_EQ(a.scene, "open");
    EXPECT_EQ(a.out_path, "w.png");
  }
  const PlotArguments log = parsedOk(parse, {"--lcm-log=s.lcm", "--request-id=12", "--channel", "T", "--out", "p.png"});
  EXPECT_EQ(log.request_id, 12);
  EXPECT_EQ(log.channel, "T");
  EXPECT_TRUE(parsedOk(parse, {"--config", "r.toml", "--out", "p.png"}).preview());
}

// One position per joint of any chain: the count is checked against the robot, not here.
TEST(PlotArguments, AtTakesOneToThreePositions) {
  EXPECT_EQ(*parsedOk(parse, {"--world", "--at", "-0.5", "--out", "w.png"}).at, planner::JointVector{{-0.5}});
  EXPECT_EQ(*parsedOk(parse, {"--world", "--at=0.2,1.57,-1.5", "--out", "w.png"}).at,
            (planner::JointVector{{0.2, 1.57, -1.5}}));
}

TEST(PlotArguments, BadInputIsNamed) {
  EXPECT_EQ(parseError(parse, {"--csv", "m.csv", "--out", "p.png", "--fast"}),
            "unknown argument '--fast' (see --help)");
  EXPECT_EQ(parseError(parse, {"--csv", "m.csv", "--out"}), "--out needs a value");
  EXPECT_EQ(parseError(parse, {"--csv=", "--out", "p.png"}), "--csv needs a value");
  EXPECT_EQ(parseError(parse, {"--csv", "m.csv"}), "missing --out FILE.png");
  EXPECT_EQ(parseError(parse, {"--world", "--at", "1,2,3,4", "--out", "p.png"}),
            "--at expects Q0,... (one position per joint, at most 3), got '1,2,3,4'");
  EXPECT_EQ(parseError(parse, {"--world", "--at=1,inf", "--out", "p.png"}),
            "--at expects Q0,... (one position per joint, at most 3), got '1,inf'");
  for (const char* at : {"", "1,", ",1", "1,,2", "1;2", "+1,2"}) {
    EXPECT_EQ(parseError(parse, {"--world", std::string("--at=") + at, "--out", "p.png"}).rfind("--at ", 0), 0U) << at;
  }
  EXPECT_EQ(parseError(parse, {"--world", "--csv", "m.csv", "--frames=1", "--out", "p.png"}),
            "--frames expects 2 to 20, got '1'");
  EXPECT_EQ(parseError(parse, {"--at", "1,2", "--out", "p.png"}), "--animation and --at need --world");
  EXPECT_EQ(parseError(parse, {"--csv", "m.csv", "--lcm-log", "s.lcm", "--out", "p.png"}),
            "give exactly one of --csv and --lcm-log");
  EXPECT_EQ(parseError(parse, {"--world", "--at", "1,2", "--animation", "a.png", "--out", "p.png"}),
            "--animation needs a trajectory (--csv or --lcm-log), not --at");
}

}  // namespace
}  // namespace cyber::tools

// cyber-plan's command line (tools/cyber-plan/plan_arguments.cpp).

#include "plan_arguments.hpp"

#include "tool_arguments_test.hpp"

namespace cyber::tools {
namespace {

auto parse = [](const std::vector<std::string>& args) { return parsePlanArguments(args); };

TEST(PlanArguments, BothSpellingsOfAValueMeanTheSame) {
  for (const auto& args : {std::vector<std::string>{"--from", "0.2,1.57", "--to", "1.97,5.17", "--from-velocity",
                                                    "-0.2,1", "--scene", "open", "--scene-offset", "0.1", "--csv",
                                                    "m.csv", "--pieces", "coral", "--json", "--csv-step", "0.0001"},
                           std::vector<std::string>{"--from=0.2,1.57", "--to=1.97,5.17", "--from-velocity=-0.2,1",
                                                    "--scene=open", "--scene-offset=0.1", "--csv=m.csv",
                                                    "--pieces=coral", "--json", "--csv-step=0.0001"}}) {
    const PlanArguments a = parsedOk(parse, args);
    EXPECT_EQ(a.from.values, (std::vector<double>{0.2, 1.57}));
    EXPECT_EQ(a.to.values, (std::vector<double>{1.97, 5.17}));
    EXPECT_EQ(a.from_velocity, (planner::JointVector{{-0.2, 1.0}}));
    EXPECT_EQ(a.scene, "open");
    EXPECT_EQ(a.csv_path, "m.csv");
    EXPECT_EQ(a.csv_step_s, 0.0001);
    EXPECT_EQ(a.pieces, "coral");
    EXPECT_DOUBLE_EQ(a.scene_offset_m, 0.1);
    EXPECT_TRUE(a.json);
  }
}

TEST(PlanArguments, BadInputIsNamed) {
  const std::vector<std::string> move = {"--from", "0,0", "--to", "1,1"};
  auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.begin(), move.begin(), move.end());
    return extra;
  };
  EXPECT_EQ(parseError(parse, with({"--fast"})), "unknown argument '--fast' (see --help)");
  EXPECT_EQ(parseError(parse, with({"--csv"})), "--csv needs a value");
  EXPECT_EQ(parseError(parse, with({"--csv="})), "--csv needs a value");
  EXPECT_EQ(parseError(parse, with({"--json=1"})), "--json takes no value, got '--json=1'");
  EXPECT_EQ(parseError(parse, {"--from", "0,0"}), "missing --to (see --help)");
  EXPECT_EQ(parseError(parse, {"--to", "0,0"}), "missing --from (see --help)");
  EXPECT_EQ(parseError(parse, with({"--scene-offset", "near"})),
            "--scene-offset expects a finite number of metres, got 'near'");
  for (const char* bad : {"0", "0.000009", "0.0011", "-0.001", "nan", "1ms"}) {
    EXPECT_EQ(parseError(parse, with({"--csv-step", bad})),
              std::string("--csv-step expects seconds from 0.00001 to 0.001, got '") + bad + "'");
  }
  EXPECT_FALSE(parsedOk(parse, move).csv_step_s) << "without --csv-step, the plan's columns choose it";
  // The count of values is checked against the robot's joints once its description is read.
  for (const char* bad : {"1,2,3,4", "1,nan", "1,2x", "STOW"}) {
    EXPECT_EQ(parseError(parse, with({"--from-velocity", bad})),
              std::string("--from-velocity expects V0,V1,... as one finite number per joint separated by ',', got '") +
                  bad + "'");
  }
}

// Names are looked up once the configuration and the held pieces are known (pose_argument_test).
TEST(PlanArguments, PosesAreNumbersOrNames) {
  const PlanArguments named = parsedOk(parse, {"--from", "STOW", "--to=L3", "--pieces", "coral"});
  EXPECT_EQ(named.from.name, "STOW");
  EXPECT_EQ(named.to.name, "L3");
  EXPECT_TRUE(named.from.values.empty());
  const PlanArguments mixed = parsedOk(parse, {"--from", "0.2,1.57", "--to", "L3"});
  EXPECT_EQ(mixed.from.values, (std::vector<double>{0.2, 1.57}));
  EXPECT_TRUE(mixed.from.name.empty());
  EXPECT_EQ(mixed.to.name, "L3");
  for (const char* bad : {"STOW,1", "1,nan", "0.2,"}) {
    EXPECT_EQ(parseError(parse, {"--from", bad, "--to", "L3"}),
              std::string("--from expects the joints' values in chain order separated by ',' (finite numbers) or a "
                          "pose name, got '") +
                  bad + "'");
  }
}

TEST(PlanArguments, HelpNeedsNoMove) { EXPECT_TRUE(parsedOk(parse, {"--help"}).help); }

}  // namespace
}  // namespace cyber::tools

#include "goal_arguments.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace cyber::tools {
namespace {

GoalArguments ok(const std::vector<std::string>& args) {
  auto parsed = parseGoalArguments(args);
  EXPECT_TRUE(parsed.ok()) << parsed.error().message;
  return parsed.ok() ? parsed.value() : GoalArguments{};
}

std::string error(const std::vector<std::string>& args) {
  auto parsed = parseGoalArguments(args);
  EXPECT_FALSE(parsed.ok());
  return parsed.ok() ? "" : parsed.error().message;
}

TEST(GoalArguments, ParsesEveryOption) {
  const GoalArguments a =
      ok({"--to", "1.25,-0.5", "--pieces", "coral,algae", "--scene", "open", "--scene-offset", "0.3", "--id", "42",
          "--lcm-url", "udpm://239.255.76.67:5810?ttl=1", "--timeout", "2.5", "--no-wait-daemon"});
  EXPECT_EQ(a.position[0], 1.25);
  EXPECT_EQ(a.position[1], -0.5);
  EXPECT_EQ(a.pieces, (std::vector<std::string>{"coral", "algae"}));
  EXPECT_EQ(a.scene, "open");
  EXPECT_EQ(a.scene_offset_m, 0.3);
  EXPECT_EQ(a.request_id, 42);
  EXPECT_EQ(a.lcm_url, "udpm://239.255.76.67:5810?ttl=1");
  EXPECT_EQ(a.timeout_s, 2.5);
  EXPECT_FALSE(a.wait_for_daemon);
}

// Not LCM's default (port 7667): the daemon's, the team-use port (docs/lcm.md).
TEST(GoalArguments, TheLcmUrlDefaultsToTheDaemons) {
  EXPECT_EQ(ok({"--to", "1,1"}).lcm_url, "udpm://239.255.76.67:5810?ttl=0");
  EXPECT_EQ(ok({"--to", "1,1"}).lcm_url, config::DaemonSettings{}.lcm_url);
  EXPECT_NE(goalUsage().find("5810"), std::string::npos);
}

TEST(GoalArguments, NonFiniteTargetsPassThroughForTheDaemonToReject) {
  const GoalArguments a = ok({"--to", "nan,inf"});
  EXPECT_TRUE(std::isnan(a.position[0]));
  EXPECT_TRUE(std::isinf(a.position[1]));
  EXPECT_TRUE(a.pieces.empty());
  EXPECT_EQ(a.scene_offset_m, 0.0);
  EXPECT_EQ(a.request_id, -1);
  EXPECT_TRUE(a.wait_for_daemon);
}

// The daemon knows the config's pieces and scene ranges; cyber-goal sends what it is given.
TEST(GoalArguments, PiecesAndOffsetsPassThroughForTheDaemonToJudge) {
  EXPECT_EQ(ok({"--to", "1,1", "--pieces", "cube,cube"}).pieces, (std::vector<std::string>{"cube", "cube"}));
  EXPECT_EQ(ok({"--to", "1,1", "--pieces", "a,b,c,d,e"}).pieces.size(), 5U);
  EXPECT_TRUE(ok({"--to", "1,1", "--pieces", "none"}).pieces.empty());
  EXPECT_TRUE(std::isnan(ok({"--to", "1,1", "--scene-offset", "nan"}).scene_offset_m));
  EXPECT_EQ(ok({"--to", "1,1", "--scene-offset", "-0.25"}).scene_offset_m, -0.25);
}

TEST(GoalArguments, BadInputIsNamed) {
  EXPECT_EQ(error({}), "--to J0,J1,... or --to NAME is required");
  EXPECT_EQ(error({"--to", "1.0,x"}), "--to expects J0,J1,... or a pose NAME, got '1.0,x'");
  EXPECT_EQ(error({"--to", "1,2", "--pieces", "coral,"}), "--pieces expects NAME[,NAME...], got 'coral,'");
  EXPECT_EQ(error({"--to", "1,2", "--scene-offset", "x"}), "--scene-offset expects metres, got 'x'");
  EXPECT_EQ(error({"--to", "1,2", "--id", "4x"}), "--id expects an integer, got '4x'");
  EXPECT_EQ(error({"--to", "1,2", "--timeout", "0"}), "--timeout expects seconds > 0, got '0'");
  EXPECT_EQ(error({"--to", "1,2", "--timeout", "nan"}), "--timeout expects seconds > 0, got 'nan'");
  EXPECT_EQ(error({"--to", "1,2", "--bogus"}), "unknown argument '--bogus' (see --help)");
  EXPECT_EQ(error({"--to"}), "--to needs a value");
  EXPECT_EQ(error({"--to="}), "--to needs a value");
  EXPECT_EQ(error({"--to", "1,2", "--scene", ""}), "--scene needs a value");
  EXPECT_EQ(error({"--to=1,2", "--no-wait-daemon=yes"}), "--no-wait-daemon takes no value, got '--no-wait-daemon=yes'");
  EXPECT_EQ(error({"--to", "L3,1"}), "--to expects J0,J1,... or a pose NAME, got 'L3,1'");
  EXPECT_EQ(error({"--to", "1,2", "--config="}), "--config needs a value");
}

// The daemon has the robot's joint count: any count of values goes, for it to judge (docs/lcm.md).
TEST(GoalArguments, AnyCountOfValuesPassesThroughForTheDaemonToJudge) {
  EXPECT_EQ(ok({"--to", "1.0"}).position, (std::vector<double>{1.0}));
  EXPECT_EQ(ok({"--to", "1,2,3"}).position, (std::vector<double>{1, 2, 3}));
  std::string many = "0";
  for (int i = 1; i < 128; ++i) many += ",0";
  EXPECT_EQ(error({"--to", many}).rfind("--to expects J0,J1,... or a pose NAME", 0), 0u)
      << "arm_goal_t counts joints in an int8_t";
}

// A pose name is sent as the name, for the daemon to resolve with its configuration (docs/lcm.md,
// "Named goals"); --config only checks it first.
TEST(GoalArguments, APoseNameIsSentWithOrWithoutAConfig) {
  const GoalArguments a = ok({"--to", "L3", "--pieces", "coral"});
  EXPECT_EQ(a.pose_name, "L3");
  EXPECT_TRUE(a.position.empty());
  EXPECT_EQ(a.config_path, "");
  const GoalArguments b = ok({"--to", "L3", "--pieces", "coral", "--config", "robot.toml"});
  EXPECT_EQ(b.pose_name, "L3");
  EXPECT_EQ(b.config_path, "robot.toml");
  EXPECT_EQ(ok({"--to=1,2", "--config=robot.toml"}).pose_name, "") << "numbers need no lookup";
}

// [poses.coral] L3 = [1.27, 5.79], [poses.none] L3 = [1.22, 5.69] in config/reefscape-2025.toml.
TEST(GoalArguments, ThePoseNameIsTheHeldSetsPose) {
  const config::Config config = config::loadEmbeddedDefaultConfig();
  auto position = [&](const std::vector<std::string>& args) {
    const auto p = goalPosition(ok(args), config);
    EXPECT_TRUE(p.ok()) << (p.ok() ? "" : p.error().message);
    return p.ok() ? p.value() : std::vector<double>{};
  };
  EXPECT_EQ(position({"--to", "L3", "--pieces", "coral", "--config", "x"}), (std::vector<double>{1.27, 5.79}));
  EXPECT_EQ(position({"--to", "L3", "--config", "x"}), (std::vector<double>{1.22, 5.69}));
  EXPECT_EQ(position({"--to", "L3", "--pieces", "none", "--config", "x"}), (std::vector<double>{1.22, 5.69}));
  EXPECT_EQ(position({"--to", "0.5,nan", "--pieces", "cone", "--config", "x"})[0], 0.5)
      << "numbers and pieces still pass through for the daemon to judge";
  auto refused = [&](const std::vector<std::string>& args) {
    const auto p = goalPosition(ok(args), config);
    EXPECT_EQ(p.status(), cli::ArgumentStatus::kBadUsage);
    return p.ok() ? "" : p.error().message;
  };
  EXPECT_EQ(refused({"--to", "HOLD_HIGH", "--pieces", "coral", "--config", "x"}),
            "--to: no pose \"HOLD_HIGH\" for the held set \"coral\" (its poses: STOW, INTAKE, L1, L2, L3, L4, NET); "
            "it is a pose of \"algae\"");
  EXPECT_EQ(refused({"--to", "L3", "--pieces", "cone", "--config", "x"}).rfind("--pieces: ", 0), 0u)
      << "the held set of a name must be the config's";
}

TEST(GoalArguments, BothSpellingsOfAValueMeanTheSame) {
  const std::vector<std::vector<std::string>> spellings = {
      {"--to", "-0.2,1", "--scene", "open", "--id", "7", "--timeout", "3", "--lcm-url", "memq://"},
      {"--to=-0.2,1", "--scene=open", "--id=7", "--timeout=3", "--lcm-url=memq://"}};
  for (const auto& args : spellings) {
    const GoalArguments a = ok(args);
    EXPECT_EQ(a.position[0], -0.2);
    EXPECT_EQ(a.position[1], 1.0);
    EXPECT_EQ(a.scene, "open");
    EXPECT_EQ(a.request_id, 7);
    EXPECT_EQ(a.timeout_s, 3.0);
    EXPECT_EQ(a.lcm_url, "memq://");
  }
}

}  // namespace
}  // namespace cyber::tools

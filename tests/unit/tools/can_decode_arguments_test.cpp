// cyber-can-decode's command line (tools/cyber-can-decode/decode_arguments.cpp).

#include "decode_arguments.hpp"

#include "tool_arguments_test.hpp"

namespace cyber::tools {
namespace {

auto parse = [](const std::vector<std::string>& args) { return parseDecodeArguments(args); };

TEST(DecodeArguments, BothSpellingsOfAValueMeanTheSame) {
  for (const auto& args :
       {std::vector<std::string>{"--csv", "--joint0-device", "5", "--joint1-device", "63", "--config", "r.toml",
                                 "log.txt"},
        std::vector<std::string>{"--csv", "--joint0-device=5", "--joint1-device=63", "--config=r.toml", "log.txt"}}) {
    const DecodeArguments a = parsedOk(parse, args);
    EXPECT_EQ(a.format, OutputFormat::kCsv);
    EXPECT_EQ(a.devices[0], 5);
    EXPECT_EQ(a.devices[1], 63);
    EXPECT_EQ(a.config_path, "r.toml");
    EXPECT_EQ(a.path, "log.txt");
  }
  EXPECT_EQ(parsedOk(parse, {"-"}).path, "-");
  EXPECT_FALSE(parsedOk(parse, {}).path);
  EXPECT_FALSE(parsedOk(parse, {}).config_path);
  EXPECT_FALSE(parsedOk(parse, {}).devices[0]);
}

TEST(DecodeArguments, JointsFromTheConfigAndOptions) {
  // The embedded reference config: elevator (m) on device 1, arm (rad) on device 2.
  JointDevices joints = jointDevices(parsedOk(parse, {}));
  EXPECT_EQ(joints.devices[0], 1);
  EXPECT_EQ(joints.devices[1], 2);
  EXPECT_EQ(joints.names[0], "elevator");
  EXPECT_EQ(joints.units[0], "m");
  EXPECT_EQ(joints.names[1], "arm");
  EXPECT_EQ(joints.units[1], "rad");
  joints = jointDevices(parsedOk(parse, {"--joint1-device", "7"}));
  EXPECT_EQ(joints.devices[0], 1);
  EXPECT_EQ(joints.devices[1], 7);
  joints = jointDevices(parsedOk(parse, {"--config", CYBER_SOURCE_DIR "/config/chargedup-2023-double-jointed.toml"}));
  EXPECT_EQ(joints.names[0], "shoulder");
  EXPECT_EQ(joints.units[0], "rad");
  EXPECT_EQ(joints.names[1], "elbow");
  EXPECT_EQ(joints.units[1], "rad");
  EXPECT_EQ(joints.devices[0], 1);
  EXPECT_EQ(joints.devices[1], 2);
}

TEST(DecodeArguments, BadInputIsNamed) {
  EXPECT_EQ(parseError(parse, {"--fast"}), "unknown argument '--fast' (see --help)");
  EXPECT_EQ(parseError(parse, {"--joint1-device"}), "--joint1-device needs a value");
  EXPECT_EQ(parseError(parse, {"--joint1-device="}), "--joint1-device needs a value");
  EXPECT_EQ(parseError(parse, {"--joint1-device=64"}), "--joint1-device must be 0..63, got '64'");
  EXPECT_EQ(parseError(parse, {"--joint0-device", "-1"}), "--joint0-device must be 0..63, got '-1'");
  EXPECT_EQ(parseError(parse, {"--elevator-device", "1"}), "unknown argument '--elevator-device' (see --help)");
  EXPECT_EQ(parseError(parse, {"--strict=1"}), "--strict takes no value, got '--strict=1'");
  EXPECT_EQ(parseError(parse, {"a.log", "b.log"}), "more than one input file");
}

// A chain of three joints: a device, a name and a unit per joint, the third overridable too.
TEST(DecodeArguments, EveryJointOfAThreeJointChain) {
  const std::string config = CYBER_SOURCE_DIR "/config/reefscape-2025-elevator-pivot-wrist.toml";
  JointDevices joints = jointDevices(parsedOk(parse, {"--config", config}));
  ASSERT_EQ(joints.devices.size(), 3u);
  EXPECT_EQ(joints.names[2], "wrist");
  EXPECT_EQ(joints.units[2], "rad");
  EXPECT_EQ(joints.devices[2], 3);
  joints = jointDevices(parsedOk(parse, {"--config", config, "--joint2-device", "9"}));
  EXPECT_EQ(joints.devices[2], 9);
  joints = jointDevices(parsedOk(parse, {"--config", CYBER_SOURCE_DIR "/config/intake-pivot.toml"}));
  ASSERT_EQ(joints.devices.size(), 1u);
  EXPECT_EQ(joints.names[0], "pivot");
}

}  // namespace
}  // namespace cyber::tools

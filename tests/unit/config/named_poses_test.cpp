// The optional [poses.*] tables: the reference robot names the public poses (the same numbers as
// tests/support/public_moves.cpp), and bad pose tables fail at load naming the key.
#include <gtest/gtest.h>

#include <algorithm>

#include "cyber/config/load_config.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"

namespace cyber::config {
namespace {

TEST(NamedPoses, ReferenceRobotNamesThePublicPoses) {
  const Config config = loadEmbeddedDefaultConfig();
  ASSERT_EQ(config.poses.size(), 3u);
  for (const char* name : {"none", "coral", "algae"}) {
    const auto found =
        std::find_if(config.poses.begin(), config.poses.end(), [&](const PoseSet& s) { return s.name == name; });
    ASSERT_NE(found, config.poses.end()) << name;
    const PoseSet& set = *found;
    EXPECT_EQ(set.pieces, test::referencePieces(set.name));
    const auto& expected = test::publicPoses(set.name);
    ASSERT_EQ(set.poses.size(), expected.size()) << set.name;
    for (const auto& pose : expected) {
      const auto it =
          std::find_if(set.poses.begin(), set.poses.end(), [&](const NamedPose& p) { return p.name == pose.name; });
      ASSERT_NE(it, set.poses.end()) << set.name << ":" << pose.name;
      EXPECT_EQ(it->q, pose.q) << set.name << ":" << pose.name;
    }
  }
}

std::string withPoses(const std::string& poses) {
  std::string text(embeddedDefaultConfig());
  const size_t at = text.find("\n[poses.none]\n") + 1;
  const size_t end = text.find("\n[daemon]\n") + 1;
  text.replace(at, end - at, poses + "\n");
  return text;
}

void expectError(const std::string& text, const std::string& key, const std::string& problem) {
  try {
    (void)parseConfig(text, "test.toml");
    ADD_FAILURE() << "accepted: " << key;
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_NE(std::string(e.what()).find(problem), std::string::npos) << e.what();
  }
}

TEST(NamedPoses, AreOptional) {
  const Config config = parseConfig(withPoses(""), "test.toml");
  EXPECT_TRUE(config.poses.empty());
  const Config coral_only = parseConfig(withPoses("[poses.coral]\nA = [0.5, 1.0]"), "test.toml");
  ASSERT_EQ(coral_only.poses.size(), 1u);
  EXPECT_EQ(coral_only.poses[0].name, "coral");
  EXPECT_EQ(coral_only.poses[0].poses[0].q, (planner::JointVector{{0.5, 1.0}}));
}

TEST(NamedPoses, BadPoseTablesAreErrors) {
  expectError(withPoses("[poses.none]\nUP = [2.5, 1.0]"), "poses.none.UP", "outside the joint ranges");
  expectError(withPoses("[poses.none]\nUP = [0.5, -1.0]"), "poses.none.UP", "outside the joint ranges");
  expectError(withPoses("[poses.none]\nUP = [0.5]"), "poses.none.UP", "");
  expectError(withPoses("[poses.none]\nUP = \"high\""), "poses.none.UP", "");
  expectError(withPoses("[poses.cone]\nUP = [0.5, 1.0]"), "poses.cone", "unknown game piece \"cone\"");
  expectError(withPoses("[poses.\"coral+cone\"]\nUP = [0.5, 1.0]"), "poses.coral+cone", "unknown game piece \"cone\"");
}

TEST(NamedPoses, ASetOfSeveralPiecesIsNamedByJoiningThemWithPlus) {
  const Config config = parseConfig(withPoses("[poses.\"coral+algae\"]\nA = [0.5, 1.0]"), "test.toml");
  ASSERT_EQ(config.poses.size(), 1u);
  EXPECT_EQ(config.poses[0].pieces, test::referencePieces("coral+algae"));
  EXPECT_EQ(config.robot.pieceSetName(config.poses[0].pieces), "algae+coral");
}

// The file's order, not the alphabet's: the first pose of the first set is where the plant
// simulator and tools/demo start the robot.
TEST(NamedPoses, KeepTheOrderOfTheFile) {
  const Config config = parseConfig(withPoses("[poses.none]\nZED = [0.5, 1.0]\nALPHA = [0.6, 1.0]\nMID = [0.7, 1.0]\n"
                                              "[poses.coral]\nB = [0.5, 1.0]\nA = [0.6, 1.0]"),
                                    "test.toml");
  ASSERT_EQ(config.poses.size(), 2u);
  EXPECT_EQ(config.poses[0].name, "none");
  ASSERT_EQ(config.poses[0].poses.size(), 3u);
  EXPECT_EQ(config.poses[0].poses[0].name, "ZED");
  EXPECT_EQ(config.poses[0].poses[1].name, "ALPHA");
  EXPECT_EQ(config.poses[0].poses[2].name, "MID");
  EXPECT_EQ(config.poses[1].poses[0].name, "B");
  // The shipped reference robot starts at STOW, its first pose.
  const Config reference = loadEmbeddedDefaultConfig();
  EXPECT_EQ(reference.poses.front().name, "none");
  EXPECT_EQ(reference.poses.front().poses.front().name, "STOW");
}

}  // namespace
}  // namespace cyber::config

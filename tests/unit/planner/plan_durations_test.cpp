// Plans are unchanged by a change that means to keep them: every ordered pair of every shipped
// robot's named poses (per pose set, with its held pieces) and the seeded random moves of
// SeededRandomMoves give, bit for bit, the durations (or refusals) stored in
// plan_durations.txt beside this file. A change that alters a plan on purpose rewrites the file
// (CYBER_WRITE_PLAN_DURATIONS=1 ./plan_durations_test) and says why in its commit; the diff of
// the file then shows which plans moved.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cyber/planner/motion_planner.hpp"
#include "seeded_moves.hpp"
#include "shipped_robots.hpp"

namespace cyber::planner {
namespace {

const char* const kStoredFile = "tests/unit/planner/plan_durations.txt";

// One line per move: its label, then its duration as a hexadecimal float (exact), or the status
// of its refusal.
std::string outcome(const test::ShippedRobot& robot, const PlanRequest& request) {
  const auto plan = robot.planner.plan(request);
  if (!plan.ok()) return "refused " + std::string(toString(plan.status()));
  char text[64];
  std::snprintf(text, sizeof text, "%a", plan.value().trajectory->duration_s());
  return text;
}

std::vector<std::string> currentDurations() {
  std::vector<std::string> lines;
  for (const char* name : test::kShippedRobotNames) {
    const test::ShippedRobot& robot = test::shippedRobot(name);
    for (const test::NamedMove& move : test::namedMoves(robot.config)) {
      lines.push_back(std::string(name) + " " + move.label + " " + outcome(robot, move.request));
    }
    test::SeededMoveDraw draw(robot, test::kSeededMovesSeed);
    for (int move = 0; move < test::kSeededMovesPerRobot; ++move) {
      const PlanRequest request = draw.next(move);
      lines.push_back(std::string(name) + " seeded " + std::to_string(move) + " " + outcome(robot, request));
    }
  }
  return lines;
}

TEST(PlanDurations, EveryNamedAndSeededMoveKeepsItsStoredDurationBitForBit) {
  const std::vector<std::string> lines = currentDurations();
  const std::string path = test::sourceFile(kStoredFile);
  if (std::getenv("CYBER_WRITE_PLAN_DURATIONS") != nullptr) {
    std::ofstream out(path);
    for (const std::string& line : lines) out << line << '\n';
    GTEST_SKIP() << "wrote " << lines.size() << " durations to " << path;
  }
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  std::vector<std::string> stored;
  for (std::string line; std::getline(in, line);) stored.push_back(line);
  ASSERT_EQ(lines.size(), stored.size()) << "a different set of moves: rewrite " << kStoredFile;
  int changed = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    EXPECT_EQ(lines[i], stored[i]) << "a plan changed";
    changed += lines[i] != stored[i] ? 1 : 0;
  }
  EXPECT_GT(lines.size(), 300U);
  RecordProperty("moves", static_cast<int>(lines.size()));
  RecordProperty("changed", changed);
}

}  // namespace
}  // namespace cyber::planner

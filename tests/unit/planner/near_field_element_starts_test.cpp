// Seeded starts a little outside the clearance from a field element, at offsets drawn
// inside the scene's range, to the named poses of each shipped robot. A band of offsets searches
// a grid of the field elements swept across the band, which blocks the nodes near such a start;
// each move must still plan at its exact offset (sound: limits, clearance at that offset, drive
// limits, columns that agree at 1 ms) or be a "no path" that a flood fill of the free space at
// that exact offset proves (free_space_components.hpp; docs/algorithm.md, "2.1 Grid and
// potential").
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/motion_planner.hpp"
#include "free_space_components.hpp"
#include "joint_grid_components.hpp"
#include "seeded_moves.hpp"
#include "shipped_robots.hpp"

namespace cyber::planner {
namespace {

constexpr int kStartsPerRobot = 20;
constexpr unsigned kSeed = 35;
// The start's distance to the nearest field element at its offset [m]: from just outside the
// clearance (0.03 m on every shipped robot) to past the width of a band (two clearances).
constexpr double kNearestM = 0.031;
constexpr double kFarthestM = 0.08;

template <typename T>
const T& pick(const std::vector<T>& items, std::mt19937& random) {
  return items[static_cast<size_t>(std::uniform_int_distribution<int>(0, static_cast<int>(items.size()) - 1)(random))];
}

// Tries of a start at one offset before another offset is drawn: far into the range the field
// elements may be out of the mechanism's reach.
constexpr int kStartTries = 20000;

// A pose within the limits whose closest obstacle at this offset is a field element, kNearestM
// to kFarthestM away; none when kStartTries draws find none.
std::optional<JointVector> nearFieldElement(const RobotModel& model, const CollisionWorld& world,
                                            std::mt19937& random) {
  const int field_elements = static_cast<int>(model.scenes.front().obstacles.size());
  for (int tries = 0; tries < kStartTries; ++tries) {
    JointVector q(model.jointCount());
    for (int j = 0; j < model.jointCount(); ++j)
      q[j] = std::uniform_real_distribution<double>(model.range(j).min, model.range(j).max)(random);
    const SignedDistance d = world.distance(q);
    if (d.value >= kNearestM && d.value <= kFarthestM && d.obstacle < field_elements) return q;
  }
  return std::nullopt;
}

struct NearMove {
  PlanRequest request;
  std::string set;  // the name of the goal's pose set
};

// A named goal that keeps the clearance at an offset drawn in the scene's range (a field element
// moved away from the robot may move toward a held piece reaching past it), from a start near a
// field element at that offset.
NearMove drawMove(const test::ShippedRobot& robot, std::mt19937& random) {
  const RobotModel& model = robot.config.robot;
  const JointRange range = model.scenes.front().offset_range_m;
  for (;;) {
    const config::PoseSet& set = pick(robot.config.poses, random);
    NearMove move{PlanRequest{}, set.name};
    move.request.pieces = set.pieces;
    move.request.scene_offset_m = std::uniform_real_distribution<double>(range.min, range.max)(random);
    move.request.goal = pick(set.poses, random).q;
    const CollisionWorld world(model, model.scenes.front(), set.pieces, move.request.scene_offset_m);
    if (world.distance(move.request.goal).value < model.clearance_m) continue;
    const std::optional<JointVector> start = nearFieldElement(model, world, random);
    if (!start) continue;
    move.request.start = *start;
    return move;
  }
}

class NearFieldElementStarts : public ::testing::TestWithParam<const char*> {};

TEST_P(NearFieldElementStarts, PlanAtTheirExactOffsetOrAreProvablyRefused) {
  const test::ShippedRobot& robot = test::shippedRobot(GetParam());
  const RobotModel& model = robot.config.robot;
  ASSERT_GT(model.scenes.front().offset_range_m.max, model.scenes.front().offset_range_m.min)
      << "the first scene moves";
  std::mt19937 random(kSeed);
  int planned = 0, refused = 0;
  for (int move = 0; move < kStartsPerRobot; ++move) {
    const auto [request, set] = drawMove(robot, random);
    const CollisionWorld world(model, model.scenes.front(), request.pieces, request.scene_offset_m);
    std::string label = GetParam();
    label.append(" move ").append(std::to_string(move)).append(" (").append(set);
    label.append(", offset ").append(std::to_string(request.scene_offset_m)).append(", ");
    label.append(test::cyberPlanArguments(request)).append(")");
    const auto plan = robot.planner.plan(request);
    if (plan.ok()) {
      const Trajectory& trajectory = *plan.value().trajectory;
      EXPECT_NEAR((trajectory.sampleMotion(0.0).q - request.start).norm(), 0.0, 1e-9) << label;
      EXPECT_NEAR((trajectory.sampleMotion(trajectory.duration_s()).q - request.goal).norm(), 0.0, 1e-9) << label;
      test::expectSound(model, trajectory, request.pieces, request.scene_offset_m, label);
      ++planned;
      continue;
    }
    ASSERT_EQ(plan.status(), PlanStatus::kNoPath) << label << ": " << plan.error().message;
    // Two joints: free_space_components.hpp; the three-joint robot: the any-joint-count fill
    // (joint_grid_components.hpp) on 2 cm / 20 mrad nodes, a few million in 3-D.
    int start_component = 0, goal_component = 0;
    if (model.jointCount() == 2) {
      const test::FreeSpaceComponents components(model, world);
      start_component = components.of(request.start);
      goal_component = components.of(request.goal);
    } else {
      const test::JointGridComponents components(model, world, 0.02);
      start_component = components.of(request.start);
      goal_component = components.of(request.goal);
    }
    EXPECT_NE(start_component, test::FreeSpaceComponents::kBlocked) << label;
    EXPECT_NE(start_component, goal_component) << label << ": refused, yet a path may exist: " << plan.error().message;
    ++refused;
  }
  EXPECT_EQ(planned + refused, kStartsPerRobot);
  RecordProperty("planned", planned);
  RecordProperty("refused", refused);
}

INSTANTIATE_TEST_SUITE_P(ShippedRobots, NearFieldElementStarts, ::testing::ValuesIn(test::kShippedRobotNames),
                         test::shippedRobotParamName);

}  // namespace
}  // namespace cyber::planner

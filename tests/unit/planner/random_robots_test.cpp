// Seeded random robots that no one tuned the planner for (random_robot.hpp; docs/testing.md,
// "Random robots"): for each, 20 seeded moves (random_moves.hpp, a quarter moving starts), each
// either sound as SeededRandomMoves judges the shipped robots' (limits and the clearance at its
// offset at 1 ms, drive limits, columns that agree, within 1.02 of the fastest ride along its own
// path) or refused with a "no path" a flood fill of the free space proves. Tuning that works on the
// shipped robots only fails here. A robot with a failing move is written to
// random-robot-SEED.toml in the working directory, its failing moves as cyber-plan commands at
// the end. CYBER_RANDOM_ROBOTS=N runs N robots instead of 30 (the nightly target
// random_robots_nightly).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/motion_planner.hpp"
#include "free_space_components.hpp"
#include "random_moves.hpp"
#include "random_robot.hpp"
#include "shipped_robots.hpp"

namespace cyber::planner {
namespace {

constexpr int kRobots = 30;
constexpr unsigned kFirstSeed = 1;
// The spacings cyber-plan --csv writes at, widest first (docs/moving-starts.md, "The CSV's
// spacing"): a plan whose 1 ms columns cannot agree within 1 % more time keeps its speed, and its
// CSV is written where they do ("Consistent columns"); the shipped robots' plans from rest all
// agree at 1 ms, so SeededRandomMoves asks that of them.
constexpr double kCsvSpacingsS[] = {1e-3, 5e-4, 2.5e-4, 1e-4, 5e-5, 2.5e-5, 1e-5};

int robotCount() {
  const char* n = std::getenv("CYBER_RANDOM_ROBOTS");
  return n != nullptr ? std::max(1, std::atoi(n)) : kRobots;
}

// Robots on which the planner fails a check today (docs/performance.md, "Seeded random moves"), in a
// disabled instantiation of their own: every other robot fails the suite, these are run by hand
// (--gtest_also_run_disabled_tests --gtest_filter='DISABLED_KnownPlannerFailures/*') until the
// planner mends them. A planner change that mends one moves it back to Seeded.
// Measured: one joint: 9, 21, 24, 27, 30 (a moving start's ride along its own path, 1.024 to 1.17:
// the path turns back where the start's velocity points away from the goal); two joints: 4 (drive
// limits); three joints: 2 (the ride, 1.022), 14 and 23 (drive limits), 17 (a refusal that is not
// "no path", and a moving start's velocity 5e-5 off).
constexpr unsigned kKnownPlannerFailures[] = {2, 4, 9, 14, 17, 21, 23, 24, 27, 30};

std::vector<unsigned> seeds(bool known_failures) {
  std::vector<unsigned> out;
  for (int i = 0; i < robotCount(); ++i) {
    const unsigned seed = kFirstSeed + static_cast<unsigned>(i);
    const bool known = std::find(std::begin(kKnownPlannerFailures), std::end(kKnownPlannerFailures), seed) !=
                       std::end(kKnownPlannerFailures);
    if (known == known_failures) out.push_back(seed);
  }
  return out;
}

int failureCount() {
  const ::testing::TestResult& result = *::testing::UnitTest::GetInstance()->current_test_info()->result();
  int failed = 0;
  for (int i = 0; i < result.total_part_count(); ++i) failed += result.GetTestPartResult(i).failed() ? 1 : 0;
  return failed;
}

// Flood fill steps, in metres of the robot's motion per joint (FreeSpaceComponents), coarsest
// first: a coarse grid proves most refusals at once, a refusal through free space within a few
// millimetres of the clearance needs a finer one. A grid of more than FreeSpaceComponents' node
// budget is skipped (a three-joint robot's finest).
constexpr double kFloodFillStepsM[] = {0.02, 0.01, 0.005, 0.0025, 0.001};

struct Tally {
  int planned = 0, refused = 0, moving = 0;
  std::vector<double> plan_ms;  // every plan's and refusal's MotionPlanner::plan total
  int finer_from_rest = 0;      // plans from rest whose columns agree only finer than 1 ms
  int finer_moving = 0;         // moving starts whose columns agree only finer than 0.1 ms
  double worst_ratio = 0.0;
};

// The fastest ride on 0.1 ms samples passes the path's turns at least as fast as one on 10 us
// samples (on the first five robots' 100 plans its ratio was at most 3e-5 below the 10 us one) and
// costs a tenth: a plan within 1.02 less kCoarseRideSlack of it is within 1.02 of the 10 us ride,
// and only the others are ridden at 10 us, as SeededRandomMoves rides every plan
// (expectNearTheFastestRide).
constexpr double kCoarseRideStepS = 1e-4;
constexpr double kCoarseRideSlack = 1e-3;

double ratioToTheFastestRide(const Trajectory& trajectory, const std::string& label) {
  const std::optional<double> coarse = fastestRideAlongPath(trajectory, kCoarseRideStepS);
  if (coarse && trajectory.duration_s() / *coarse <= 1.02 - kCoarseRideSlack) return trajectory.duration_s() / *coarse;
  return test::expectNearTheFastestRide(trajectory, label);
}

// The widest spacing at which the columns agree as expectSound judges them (its last, where
// expectSound then fails, when none does).
double csvSpacing(const Trajectory& trajectory) {
  for (double step_s : kCsvSpacingsS) {
    const ColumnConsistency columns = columnConsistency(trajectory, step_s);
    if (columns.position_error <= 0.01 && columns.velocity_error <= 0.02) return step_s;
  }
  return kCsvSpacingsS[std::size(kCsvSpacingsS) - 1];
}

class RandomRobots : public ::testing::TestWithParam<unsigned> {
 protected:
  // The refusal of `request` is a "no path" that the free space's components prove.
  void expectProvedRefusal(const RobotModel& model, const PlanRequest& request, const Result<Plan>& plan,
                           const std::string& label) {
    if (plan.status() != PlanStatus::kNoPath) {
      ADD_FAILURE() << label << ": refused with " << toString(plan.status()) << ": " << plan.error().message;
      return;
    }
    // The flood fill's slack grows with its step and may join components across a narrow wall; a
    // finer grid is tried before the refusal is called unproven.
    std::string tried;
    for (double step_m : kFloodFillStepsM) {
      test::FreeSpaceComponents& components = componentsOf(model, request, step_m);
      const auto verdict = components.separated(request.start, request.goal);
      if (verdict == test::FreeSpaceComponents::Verdict::kTooFine) continue;
      tried.append(fmt::format(" {} m", step_m));
      EXPECT_NE(verdict, test::FreeSpaceComponents::Verdict::kBlocked) << label << ": a pose on no free node";
      if (verdict != test::FreeSpaceComponents::Verdict::kJoined) return;
    }
    ADD_FAILURE() << label << ": refused, yet a path may exist (joined at every flood fill step:" << tried << ")";
  }

  struct Components {
    std::unique_ptr<CollisionWorld> world;
    std::unique_ptr<test::FreeSpaceComponents> components;
  };

  test::FreeSpaceComponents& componentsOf(const RobotModel& model, const PlanRequest& request, double step_m) {
    Components& slot = components_[{request.pieces.index(), request.scene_offset_m, step_m}];
    if (!slot.components) {
      slot.world =
          std::make_unique<CollisionWorld>(model, model.scenes.front(), request.pieces, request.scene_offset_m);
      slot.components = std::make_unique<test::FreeSpaceComponents>(model, *slot.world, step_m);
    }
    return *slot.components;
  }

  // What SeededRandomMoves asks of every plan of a shipped robot.
  void expectSoundPlan(const RobotModel& model, const PlanRequest& request, const Plan& plan, const std::string& label,
                       Tally& tally) {
    const Trajectory& trajectory = *plan.trajectory;
    EXPECT_NEAR((trajectory.sampleMotion(0.0).q - request.start).norm(), 0.0, 1e-9) << label;
    EXPECT_NEAR((trajectory.sampleMotion(0.0).qdot - request.start_velocity).norm(), 0.0, 1e-6) << label;
    EXPECT_NEAR((trajectory.sampleMotion(trajectory.duration_s()).q - request.goal).norm(), 0.0, 1e-9) << label;
    const bool moving_start = !request.start_velocity.isZero();
    const double spacing_s = csvSpacing(trajectory);
    test::expectSound(model, trajectory, request.pieces, request.scene_offset_m, label, spacing_s);
    tally.finer_from_rest += !moving_start && spacing_s < 1e-3 ? 1 : 0;
    tally.finer_moving += moving_start && spacing_s < 1e-4 ? 1 : 0;
    tally.worst_ratio = std::max(tally.worst_ratio, ratioToTheFastestRide(trajectory, label));
    ++tally.planned;
    tally.moving += moving_start ? 1 : 0;
  }

  std::map<std::tuple<int, double, double>, Components> components_;
};

// Every number as the shortest text that reads back as the same double: a moving start's state
// to 9 digits is another move.
std::string perJoint(const JointVector& v) {
  std::string out;
  for (int j = 0; j < v.size(); ++j) out.append(j == 0 ? "" : ",").append(fmt::format("{}", v[j]));
  return out;
}

std::string cyberPlanCommand(const RobotModel& model, const PlanRequest& request, const std::string& file) {
  return fmt::format(
      "build/tools/cyber-plan/cyber-plan --config {} --pieces {} --scene-offset {} --from={} --to={} "
      "--from-velocity={}",
      file, model.pieceSetName(request.pieces), request.scene_offset_m, perJoint(request.start), perJoint(request.goal),
      perJoint(request.start_velocity));
}

TEST_P(RandomRobots, EveryPlanIsSoundAndEveryRefusalHasProvablyNoPath) {
  const test::RandomRobot robot = test::randomRobot(GetParam());
  const RobotModel& model = robot.config.robot;
  const std::string file = model.name + ".toml";
  const auto planner = MotionPlanner::create(model);
  ASSERT_TRUE(planner.ok()) << planner.error().message << "\n" << robot.toml;
  test::RandomMoveDraw draw(robot, planner.value(), robot.seed);
  Tally tally;
  std::string failing;
  for (int move = 0; move < test::kRandomMovesPerRobot; ++move) {
    const auto request = draw.next(move);
    ASSERT_TRUE(request) << model.name << " move " << move << ": no clear pose in its world";
    const std::string command = cyberPlanCommand(model, *request, file);
    const std::string label = fmt::format("{} move {}: {}", model.name, move, command);
    const int failures_before = failureCount();
    const auto t0 = std::chrono::steady_clock::now();
    const auto plan = planner.value().plan(*request);
    tally.plan_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (plan.ok()) {
      expectSoundPlan(model, *request, plan.value(), label, tally);
    } else {
      expectProvedRefusal(model, *request, plan, label);
      ++tally.refused;
    }
    if (failureCount() > failures_before) failing.append(fmt::format("# failing move {}: {}\n", move, command));
  }
  if (!failing.empty()) {
    const bool saved = test::saveRandomRobot(robot, file, failing);
    ADD_FAILURE() << "reproducer " << (saved ? "" : "NOT ") << "written to " << std::filesystem::absolute(file).string()
                  << "\n"
                  << failing;
  }
  EXPECT_GT(tally.moving, 0) << model.name << ": moving starts are planned";
  RecordProperty("robot", robot.toml.substr(0, robot.toml.find("\n\n")));
  RecordProperty("joints", model.jointCount());
  std::string plan_ms;
  for (double ms : tally.plan_ms) plan_ms.append(plan_ms.empty() ? "" : " ").append(fmt::format("{:.3f}", ms));
  RecordProperty("plan_ms", plan_ms);
  RecordProperty("planned", tally.planned);
  RecordProperty("refused", tally.refused);
  RecordProperty("moving", tally.moving);
  RecordProperty("finer_than_1ms_from_rest", tally.finer_from_rest);
  RecordProperty("finer_than_0.1ms_moving", tally.finer_moving);
  RecordProperty("worst_ratio_to_ride", std::to_string(tally.worst_ratio));
}

std::string seedName(const ::testing::TestParamInfo<unsigned>& info) { return fmt::format("seed_{}", info.param); }

INSTANTIATE_TEST_SUITE_P(Seeded, RandomRobots, ::testing::ValuesIn(seeds(false)), seedName);
INSTANTIATE_TEST_SUITE_P(DISABLED_KnownPlannerFailures, RandomRobots, ::testing::ValuesIn(seeds(true)), seedName);

}  // namespace
}  // namespace cyber::planner

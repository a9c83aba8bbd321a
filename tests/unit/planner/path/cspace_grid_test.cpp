// The reference robot's grids: blocked nodes follow d(q), and the inflation makes every step
// between adjacent free nodes keep the clearance along the whole step.

#include "path/cspace_grid.hpp"

#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "reference_model.hpp"

namespace cyber::planner {
namespace {

const RobotModel& model() { return test::referenceModel(); }

struct Grids {
  std::vector<CollisionWorld> worlds;
  std::vector<CSpaceGrid> grids;
};

const Grids& grids() {
  static const Grids g = [] {
    Grids out;
    for (int set = 0; set < model().pieceSetCount(); ++set) {
      out.worlds.emplace_back(model(), model().scenes.front(), HeldPieces::fromIndex(set));
    }
    for (const CollisionWorld& world : out.worlds) out.grids.push_back(CSpaceGrid::build(world, model()));
    return out;
  }();
  return g;
}

TEST(CSpaceGrid, BlockedNodesAreThoseCloserThanTheClearance) {
  for (int set = 0; set < model().pieceSetCount(); ++set) {
    const CSpaceGrid& grid = grids().grids[static_cast<size_t>(set)];
    const CollisionWorld& world = grids().worlds[static_cast<size_t>(set)];
    EXPECT_EQ(grid.clearance_m(), model().clearance_m);
    EXPECT_GT(grid.checkedStepCount(), 0);
    EXPECT_LE(grid.firstAxis().step, model().planner.grid.step[0]);
    EXPECT_LE(grid.secondAxis().step, model().planner.grid.step[1]);
    for (int c = 0; c < grid.cellCount(); c += 7) {
      EXPECT_EQ(grid.blocked(c), world.distance(grid.node(c)).value < model().clearance_m) << c;
      if (grid.blocked(c)) {
        EXPECT_FLOAT_EQ(grid.potential(c), 1.0F);
      }
    }
    EXPECT_GT(grid.blockedCount(), grid.cellCount() / 20);
    EXPECT_LT(grid.blockedCount(), grid.cellCount());
  }
  // More geometry blocks more nodes.
  EXPECT_GE(grids().grids[3].blockedCount(), grids().grids[1].blockedCount());
  EXPECT_GT(grids().grids[1].blockedCount(), grids().grids[0].blockedCount());
}

TEST(CSpaceGrid, FreeStepsKeepTheClearanceAlongTheirLength) {
  std::mt19937 rng(31);
  for (int set = 0; set < model().pieceSetCount(); ++set) {
    const CSpaceGrid& grid = grids().grids[static_cast<size_t>(set)];
    const CollisionWorld& world = grids().worlds[static_cast<size_t>(set)];
    std::uniform_int_distribution<int> any(0, grid.cellCount() - 1);
    std::uniform_int_distribution<int> offset(-1, 1);
    int checked = 0;
    double closest = 1e9;
    while (checked < 500) {
      const int a = any(rng);
      const int di = offset(rng), dj = offset(rng);
      const int i = grid.firstIndex(a) + di, j = grid.secondIndex(a) + dj;
      if ((di == 0 && dj == 0) || i < 0 || j < 0 || i >= grid.firstAxis().count || j >= grid.secondAxis().count)
        continue;
      const int b = grid.cell(i, j);
      // Only steps near the obstacles say anything.
      if (grid.blocked(a) || grid.blocked(b) || world.distance(grid.node(a)).value > model().clearance_m + 0.02)
        continue;
      EXPECT_EQ(grid.stepFree(a, di, dj), grid.stepFree(b, -di, -dj));
      if (!grid.stepFree(a, di, dj)) continue;
      ++checked;
      // Steps are at most 0.02 m / 0.02 rad: 40 intervals are 0.5 mm apart.
      for (int k = 0; k <= 40; ++k) {
        const JointVector q = grid.node(a) + (grid.node(b) - grid.node(a)) * (k / 40.0);
        const double d = world.distance(q).value;
        closest = std::min(closest, d);
        ASSERT_GE(d, model().clearance_m)
            << "set " << set << " between " << grid.node(a).transpose() << " and " << grid.node(b).transpose();
      }
    }
    EXPECT_LT(closest, model().clearance_m + 0.002) << "the sampled steps came near the clearance";
    int refused = 0;
    for (int c = 0; c < grid.cellCount(); ++c) {
      const int i = grid.firstIndex(c), j = grid.secondIndex(c);
      if (grid.blocked(c) || i + 1 >= grid.firstAxis().count || j + 1 >= grid.secondAxis().count) continue;
      for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{0, 1}, std::pair{1, 1}}) {
        if (!grid.blocked(grid.cell(i + di, j + dj)) && !grid.stepFree(c, di, dj)) ++refused;
      }
    }
    std::printf("set %d: %d blocked nodes, %d steps checked, %d refused\n", set, grid.blockedCount(),
                grid.checkedStepCount(), refused);
  }
}

}  // namespace
}  // namespace cyber::planner

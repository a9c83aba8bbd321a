// A* against an independent Dijkstra on seeded random grids, and the grid's distance-transform
// potential against a brute-force shortest distance to the blocked set.

#include "path/astar_search.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "path/cspace_grid.hpp"

namespace cyber::planner {
namespace {

CSpaceGrid randomGrid(std::mt19937& rng, int ni, int nj, double blocked_fraction, double weight) {
  std::bernoulli_distribution is_blocked(blocked_fraction);
  std::vector<std::uint8_t> blocked(static_cast<size_t>(ni * nj));
  for (auto& b : blocked) b = is_blocked(rng) ? 1 : 0;
  SearchSettings search;
  search.potential_weight = weight;
  search.potential_range = 0.1;
  return CSpaceGrid({GridAxis{0.0, 0.02, ni}, GridAxis{1.0, 0.05, nj}}, std::move(blocked), JointVector{{1.0, 0.1}},
                    search);
}

double stepCost(const CSpaceGrid& grid, int a, int b) {
  const JointVector d = grid.node(b) - grid.node(a);
  const double length = std::sqrt(grid.metric()[0] * d[0] * d[0] + grid.metric()[1] * d[1] * d[1]);
  return length * (1.0 + grid.potentialWeight() * 0.5 * (grid.potential(a) + grid.potential(b)));
}

// Textbook Dijkstra with an O(V^2) selection: no heap, no heuristic, nothing shared with A*.
double dijkstraCost(const CSpaceGrid& grid, const std::vector<SearchEndpoint>& sources,
                    const std::vector<SearchEndpoint>& goals) {
  const int n = grid.cellCount();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> dist(static_cast<size_t>(n), inf);
  std::vector<bool> done(static_cast<size_t>(n), false);
  for (const auto& s : sources) {
    if (!grid.blocked(s.cell)) dist[static_cast<size_t>(s.cell)] = std::min(dist[static_cast<size_t>(s.cell)], s.cost);
  }
  for (;;) {
    int u = -1;
    for (int c = 0; c < n; ++c) {
      if (!done[static_cast<size_t>(c)] && std::isfinite(dist[static_cast<size_t>(c)]) &&
          (u < 0 || dist[static_cast<size_t>(c)] < dist[static_cast<size_t>(u)])) {
        u = c;
      }
    }
    if (u < 0) break;
    done[static_cast<size_t>(u)] = true;
    const int i = grid.firstIndex(u), j = grid.secondIndex(u);
    for (int di = -1; di <= 1; ++di) {
      for (int dj = -1; dj <= 1; ++dj) {
        const int a = i + di, b = j + dj;
        if ((di == 0 && dj == 0) || a < 0 || b < 0 || a >= grid.firstAxis().count || b >= grid.secondAxis().count)
          continue;
        const int v = grid.cell(a, b);
        if (grid.blocked(v)) continue;
        dist[static_cast<size_t>(v)] =
            std::min(dist[static_cast<size_t>(v)], dist[static_cast<size_t>(u)] + stepCost(grid, u, v));
      }
    }
  }
  double best = inf;
  for (const auto& g : goals) {
    if (!grid.blocked(g.cell)) best = std::min(best, dist[static_cast<size_t>(g.cell)] + g.cost);
  }
  return best;
}

double weightedDistance(const CSpaceGrid& grid, const JointVector& a, const JointVector& b) {
  const JointVector d = a - b;
  return std::sqrt(grid.metric()[0] * d[0] * d[0] + grid.metric()[1] * d[1] * d[1]);
}

TEST(AstarSearch, CostEqualsDijkstraOnRandomGrids) {
  std::mt19937 rng(2025);
  int found = 0, unreachable = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::uniform_int_distribution<int> size(4, 18);
    const int ni = size(rng), nj = size(rng);
    const CSpaceGrid grid = randomGrid(rng, ni, nj, 0.3, trial % 3 == 0 ? 0.0 : 3.0);
    std::uniform_int_distribution<int> any_cell(0, grid.cellCount() - 1);
    // A target pose near a random node; goals are nodes around it with at least the weighted
    // distance as connection cost (the admissibility precondition), sometimes more.
    const JointVector target = grid.node(any_cell(rng)) + JointVector{{0.004, -0.01}};
    std::vector<SearchEndpoint> sources, goals;
    std::uniform_real_distribution<double> extra(0.0, 0.05);
    for (int k = 0; k < 1 + trial % 3; ++k) sources.push_back({any_cell(rng), extra(rng)});
    for (int c = 0; c < grid.cellCount(); ++c) {
      if (weightedDistance(grid, grid.node(c), target) < 0.03) {
        goals.push_back({c, weightedDistance(grid, grid.node(c), target) + (trial % 2 == 0 ? extra(rng) : 0.0)});
      }
    }
    const double expected = dijkstraCost(grid, sources, goals);
    const auto astar = astarSearch(grid, sources, goals, target);
    const auto dijkstra = astarSearch(grid, sources, goals, target, SearchOptions{.use_heuristic = false});
    if (!std::isfinite(expected)) {
      ++unreachable;
      EXPECT_FALSE(astar.has_value()) << "trial " << trial;
      EXPECT_FALSE(dijkstra.has_value()) << "trial " << trial;
      continue;
    }
    ++found;
    ASSERT_TRUE(astar.has_value()) << "trial " << trial;
    ASSERT_TRUE(dijkstra.has_value()) << "trial " << trial;
    EXPECT_NEAR(astar->cost, expected, 1e-9) << "trial " << trial;
    EXPECT_NEAR(dijkstra->cost, expected, 1e-9) << "trial " << trial;
    EXPECT_LE(astar->expanded, dijkstra->expanded + 1);
    // A cost cap just below the optimum finds nothing, one at it the same path.
    EXPECT_FALSE(astarSearch(grid, sources, goals, target, SearchOptions{.max_cost = expected - 1e-9}).has_value());
    const auto capped = astarSearch(grid, sources, goals, target, SearchOptions{.max_cost = expected + 1e-9});
    ASSERT_TRUE(capped.has_value()) << "trial " << trial;
    EXPECT_NEAR(capped->cost, expected, 1e-9);
    // The returned path is a chain of free 8-neighbours whose costs add up to the cost.
    ASSERT_GE(astar->source, 0);
    ASSERT_GE(astar->goal, 0);
    EXPECT_EQ(astar->cells.front(), sources[static_cast<size_t>(astar->source)].cell);
    EXPECT_EQ(astar->cells.back(), goals[static_cast<size_t>(astar->goal)].cell);
    double total = sources[static_cast<size_t>(astar->source)].cost + goals[static_cast<size_t>(astar->goal)].cost;
    for (size_t k = 0; k < astar->cells.size(); ++k) {
      EXPECT_FALSE(grid.blocked(astar->cells[k]));
      if (k == 0) continue;
      const int a = astar->cells[k - 1], b = astar->cells[k];
      EXPECT_LE(std::abs(grid.firstIndex(a) - grid.firstIndex(b)), 1);
      EXPECT_LE(std::abs(grid.secondIndex(a) - grid.secondIndex(b)), 1);
      EXPECT_NE(a, b);
      total += stepCost(grid, a, b);
    }
    EXPECT_NEAR(total, astar->cost, 1e-9) << "trial " << trial;
  }
  EXPECT_GT(found, 150);
  EXPECT_GT(unreachable, 10);
}

TEST(AstarSearch, BlockedOrMissingEndpointsFindNothing) {
  std::vector<std::uint8_t> blocked(25, 0);
  blocked[12] = 1;
  const CSpaceGrid grid({GridAxis{0.0, 0.1, 5}, GridAxis{0.0, 0.1, 5}}, blocked, JointVector{{1.0, 1.0}},
                        SearchSettings{});
  const std::vector<SearchEndpoint> sources{{0, 0.0}};
  EXPECT_FALSE(astarSearch(grid, sources, std::vector<SearchEndpoint>{{12, 0.0}}, grid.node(12)).has_value());
  EXPECT_FALSE(astarSearch(grid, sources, std::vector<SearchEndpoint>{}, grid.node(12)).has_value());
  EXPECT_FALSE(astarSearch(grid, sources, std::vector<SearchEndpoint>{{99, 0.0}}, grid.node(4)).has_value());
  EXPECT_FALSE(
      astarSearch(grid, std::vector<SearchEndpoint>{{12, 0.0}}, std::vector<SearchEndpoint>{{24, 0.0}}, grid.node(24))
          .has_value());
  // A source that is also a goal: a one-node path.
  const auto same = astarSearch(grid, sources, std::vector<SearchEndpoint>{{0, 0.5}}, grid.node(0));
  ASSERT_TRUE(same.has_value());
  EXPECT_EQ(same->cells.size(), 1U);
  EXPECT_DOUBLE_EQ(same->cost, 0.5);
}

TEST(AstarSearch, WallWithoutGapIsUnreachable) {
  std::vector<std::uint8_t> blocked(7 * 7, 0);
  for (int j = 0; j < 7; ++j) blocked[static_cast<size_t>(3 * 7 + j)] = 1;
  const CSpaceGrid grid({GridAxis{0.0, 0.1, 7}, GridAxis{0.0, 0.1, 7}}, blocked, JointVector{{1.0, 1.0}},
                        SearchSettings{});
  EXPECT_FALSE(astarSearch(grid, std::vector<SearchEndpoint>{{grid.cell(0, 0), 0.0}},
                           std::vector<SearchEndpoint>{{grid.cell(6, 6), 0.0}}, grid.node(grid.cell(6, 6)))
                   .has_value());
}

// A grid with a square hole in its middle and, on random grids, random extra blocked nodes: the
// search on each side of the hole returns a path with that parity, the cheaper side costs what
// the unconstrained search costs, and on the clean grid the two sides pass above and below.
TEST(AstarSearch, SideOfHoleFindsTheCheapestPathOnThatSide) {
  std::mt19937 rng(11);
  int both_sides = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int ni = 13, nj = 11;
    std::bernoulli_distribution is_blocked(trial == 0 ? 0.0 : 0.15);
    std::vector<std::uint8_t> blocked(static_cast<size_t>(ni * nj));
    for (auto& b : blocked) b = is_blocked(rng) ? 1 : 0;
    for (int i = 5; i <= 7; ++i) {
      for (int j = 4; j <= 6; ++j) blocked[static_cast<size_t>(i * nj + j)] = 1;
    }
    const int source = 0 * nj + 5, goal = 12 * nj + 5;
    blocked[static_cast<size_t>(source)] = blocked[static_cast<size_t>(goal)] = 0;
    SearchSettings search;
    search.potential_weight = trial % 2 == 0 ? 0.0 : 2.0;
    search.potential_range = 0.1;
    const CSpaceGrid grid({GridAxis{0.0, 0.02, ni}, GridAxis{1.0, 0.05, nj}}, blocked, JointVector{{1.0, 0.1}}, search);
    // The square is a hole unless random nodes join it to the edge.
    const GridHole* square = nullptr;
    for (const GridHole& hole : grid.holes()) {
      if (hole.i >= 5 && hole.i + 1 <= 7 && hole.j >= 4 && hole.j <= 6) square = &hole;
    }
    if (trial == 0) {
      ASSERT_NE(square, nullptr);
      EXPECT_EQ(square->cells, 9);
    }
    if (square == nullptr) continue;
    const std::vector<SearchEndpoint> sources{{source, 0.0}}, goals{{goal, 0.0}};
    const auto free = astarSearch(grid, sources, goals, grid.node(goal));
    std::optional<SearchPath> side[2];
    for (int parity : {0, 1}) {
      side[parity] =
          astarSearch(grid, sources, goals, grid.node(goal), SearchOptions{.side = SideOfHole{*square, parity}});
      if (!side[parity]) continue;
      EXPECT_EQ(rayCrossingParity(grid, *square, side[parity]->cells), parity) << "trial " << trial;
      EXPECT_EQ(side[parity]->cells.front(), source);
      EXPECT_EQ(side[parity]->cells.back(), goal);
      ASSERT_TRUE(free.has_value());
      EXPECT_GE(side[parity]->cost, free->cost - 1e-12);
    }
    if (!free) {
      EXPECT_FALSE(side[0] || side[1]) << "trial " << trial;
      continue;
    }
    const double cheaper = std::min(side[0] ? side[0]->cost : INFINITY, side[1] ? side[1]->cost : INFINITY);
    EXPECT_NEAR(cheaper, free->cost, 1e-9) << "trial " << trial;
    if (!side[0] || !side[1]) continue;
    ++both_sides;
    if (trial == 0) {
      // The ray runs up from the square: the path above crosses it once, the path below never.
      for (int parity : {0, 1}) {
        for (int cell : side[parity]->cells) {
          if (grid.firstIndex(cell) == 6) {
            EXPECT_EQ(grid.secondIndex(cell) > 6, parity == 1);
          }
        }
      }
      EXPECT_NEAR(side[0]->cost, side[1]->cost, 1e-9) << "the grid is symmetric about the middle row";
    }
  }
  EXPECT_GT(both_sides, 50);
}

// The side-of-hole search's heuristic (the way through the ray on the wrong side) must keep the
// search exact: its cost equals the search's without a heuristic, from random sources to random
// goals (either side of the ray, above and below the hole), and max_cost cuts exactly there.
TEST(AstarSearch, SideOfHoleHeuristicKeepsTheCost) {
  std::mt19937 rng(23);
  int compared = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const int ni = 15, nj = 13;
    std::bernoulli_distribution is_blocked(0.12);
    std::vector<std::uint8_t> blocked(static_cast<size_t>(ni * nj));
    for (auto& b : blocked) b = is_blocked(rng) ? 1 : 0;
    for (int i = 6; i <= 8; ++i) {
      for (int j = 5; j <= 7; ++j) blocked[static_cast<size_t>(i * nj + j)] = 1;
    }
    SearchSettings search;
    search.potential_weight = trial % 2 == 0 ? 0.0 : 2.0;
    search.potential_range = 0.1;
    const CSpaceGrid grid({GridAxis{0.0, 0.02, ni}, GridAxis{1.0, 0.05, nj}}, blocked, JointVector{{1.0, 0.1}}, search);
    if (grid.holes().empty()) continue;
    std::uniform_int_distribution<int> any_cell(0, grid.cellCount() - 1);
    const int source = any_cell(rng), goal = any_cell(rng);
    if (grid.blocked(source) || grid.blocked(goal)) continue;
    const std::vector<SearchEndpoint> sources{{source, 0.0}}, goals{{goal, 0.0}};
    for (int parity : {0, 1}) {
      const SideOfHole side{grid.holes().front(), parity};
      const auto with = astarSearch(grid, sources, goals, grid.node(goal), SearchOptions{.side = side});
      const auto without =
          astarSearch(grid, sources, goals, grid.node(goal), SearchOptions{.use_heuristic = false, .side = side});
      ASSERT_EQ(with.has_value(), without.has_value()) << "trial " << trial;
      if (!with) continue;
      ++compared;
      EXPECT_NEAR(with->cost, without->cost, 1e-9) << "trial " << trial;
      EXPECT_FALSE(astarSearch(grid, sources, goals, grid.node(goal),
                               SearchOptions{.side = side, .max_cost = with->cost * (1.0 - 1e-6)})
                       .has_value());
      EXPECT_TRUE(astarSearch(grid, sources, goals, grid.node(goal),
                              SearchOptions{.side = side, .max_cost = with->cost * (1.0 + 1e-6)})
                      .has_value());
    }
  }
  EXPECT_GT(compared, 100);
}

// Free nodes share a region exactly when a path joins them (the textbook Dijkstra reaches one
// from the other); blocked nodes have none.
TEST(CSpaceGrid, RegionsAreTheConnectedFreeNodes) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 40; ++trial) {
    const CSpaceGrid grid = randomGrid(rng, 9, 8, 0.3 + 0.01 * trial, 0.0);
    std::uniform_int_distribution<int> any_cell(0, grid.cellCount() - 1);
    for (int pair = 0; pair < 10; ++pair) {
      const int a = any_cell(rng), b = any_cell(rng);
      if (grid.blocked(a)) {
        EXPECT_EQ(grid.region(a), -1);
        continue;
      }
      if (grid.blocked(b)) continue;
      const bool joined = std::isfinite(dijkstraCost(grid, {{a, 0.0}}, {{b, 0.0}}));
      EXPECT_EQ(grid.region(a) == grid.region(b), joined) << "trial " << trial;
    }
  }
}

TEST(CSpaceGrid, HolesAreTheBlockedRegionsAwayFromTheEdges) {
  const int ni = 12, nj = 10;
  std::vector<std::uint8_t> blocked(static_cast<size_t>(ni * nj), 0);
  auto block = [&](int i, int j) { blocked[static_cast<size_t>(i * nj + j)] = 1; };
  block(2, 2), block(3, 2), block(3, 3), block(4, 4);  // a hole of 4 nodes, diagonally joined
  for (int j = 0; j < 4; ++j) block(8, j);             // touches the edge: not a hole
  block(8, 7), block(9, 7), block(8, 6);               // a hole of 3 nodes
  block(5, 8);                                         // one node wide: no ray foot, left out
  const CSpaceGrid grid({GridAxis{0.0, 0.1, ni}, GridAxis{0.0, 0.1, nj}}, blocked, JointVector{{1.0, 1.0}},
                        SearchSettings{});
  ASSERT_EQ(grid.holes().size(), 2U);
  EXPECT_EQ(grid.holes()[0].cells, 4);
  EXPECT_EQ(grid.holes()[0].i, 2);
  EXPECT_EQ(grid.holes()[0].j, 2);
  EXPECT_EQ(grid.holes()[1].cells, 3);
  EXPECT_EQ(grid.holes()[1].i, 8);
  EXPECT_EQ(grid.holes()[1].j, 7);
  // The ray leaves upward between columns 8 and 9 above row 7.
  EXPECT_TRUE(grid.crossesRay(grid.holes()[1], grid.cell(8, 9), 1, 0));
  EXPECT_TRUE(grid.crossesRay(grid.holes()[1], grid.cell(9, 8), -1, 1));
  EXPECT_FALSE(grid.crossesRay(grid.holes()[1], grid.cell(8, 5), 1, 0));
  EXPECT_FALSE(grid.crossesRay(grid.holes()[1], grid.cell(8, 9), 0, -1));
  EXPECT_FALSE(grid.crossesRay(grid.holes()[1], grid.cell(7, 9), 1, 0));
}

TEST(CSpaceGrid, PotentialIsTheDistanceTransformOfTheBlockedNodes) {
  std::mt19937 rng(9);
  for (int trial = 0; trial < 30; ++trial) {
    const CSpaceGrid grid = randomGrid(rng, 12, 15, 0.08, 1.0);
    // Brute force: Dijkstra from all blocked nodes over the free 8-neighbour graph of weighted
    // step lengths (the chamfer metric), blocked nodes not excluded as intermediate nodes.
    const int n = grid.cellCount();
    std::vector<double> dist(static_cast<size_t>(n), std::numeric_limits<double>::infinity());
    std::vector<bool> done(static_cast<size_t>(n), false);
    for (int c = 0; c < n; ++c) {
      if (grid.blocked(c)) dist[static_cast<size_t>(c)] = 0.0;
    }
    for (;;) {
      int u = -1;
      for (int c = 0; c < n; ++c) {
        if (!done[static_cast<size_t>(c)] && std::isfinite(dist[static_cast<size_t>(c)]) &&
            (u < 0 || dist[static_cast<size_t>(c)] < dist[static_cast<size_t>(u)]))
          u = c;
      }
      if (u < 0) break;
      done[static_cast<size_t>(u)] = true;
      for (int di = -1; di <= 1; ++di) {
        for (int dj = -1; dj <= 1; ++dj) {
          const int a = grid.firstIndex(u) + di, b = grid.secondIndex(u) + dj;
          if (a < 0 || b < 0 || a >= 12 || b >= 15) continue;
          const int v = grid.cell(a, b);
          dist[static_cast<size_t>(v)] =
              std::min(dist[static_cast<size_t>(v)], dist[static_cast<size_t>(u)] + grid.stepLength(di, dj));
        }
      }
    }
    for (int c = 0; c < n; ++c) {
      const double x = std::max(0.0, 1.0 - dist[static_cast<size_t>(c)] / 0.1);
      EXPECT_NEAR(grid.potential(c), x * x, 1e-6) << "trial " << trial << " cell " << c;
    }
  }
}

TEST(CSpaceGrid, AxisCoversTheRangeWithNodesAtBothEnds) {
  const GridAxis axis = GridAxis::covering(JointRange{0.0, 6.108652381980153}, 0.02);
  EXPECT_EQ(axis.count, 307);
  EXPECT_LE(axis.step, 0.02);
  EXPECT_DOUBLE_EQ(axis.at(0), 0.0);
  EXPECT_NEAR(axis.at(axis.count - 1), 6.108652381980153, 1e-12);
  const GridAxis exact = GridAxis::covering(JointRange{0.0, 2.0}, 0.02);
  EXPECT_EQ(exact.count, 101);
  const GridAxis point = GridAxis::covering(JointRange{1.0, 1.0}, 0.02);
  EXPECT_EQ(point.count, 1);
}

TEST(CSpaceGrid, LowerCornerClampsToTheGrid) {
  const CSpaceGrid grid({GridAxis{0.0, 0.1, 5}, GridAxis{0.0, 0.1, 5}}, std::vector<std::uint8_t>(25, 0),
                        JointVector{{1.0, 1.0}}, SearchSettings{});
  EXPECT_EQ(grid.lowerCorner(JointVector{{0.25, 0.31}}), grid.cell(2, 3));
  EXPECT_EQ(grid.lowerCorner(JointVector{{-1.0, 9.0}}), grid.cell(0, 4));
  EXPECT_EQ(grid.blockedCount(), 0);
}

}  // namespace
}  // namespace cyber::planner

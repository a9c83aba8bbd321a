#pragma once
// The improved A* of algorithm.md section 2.2 on a CSpaceGrid: 8-connected, step cost
//   |step|_Sigma * (1 + potential_weight * (p(a) + p(b)) / 2)
// (the weighted length plus the weight times the potential integrated along the step), and the
// heuristic h(n) = |node(n) - target|_Sigma. Several source and goal nodes may be given, each with
// the cost of connecting it to the exact start or goal pose.

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "path/cspace_grid.hpp"

namespace cyber::planner {

struct SearchEndpoint {
  int cell = 0;
  double cost = 0.0;  // cost of the connection between the exact pose and this node
};

struct SearchPath {
  std::vector<int> cells;  // from a source node to a goal node
  double cost = 0.0;       // source connection + steps + goal connection
  int source = -1;         // index into the sources given
  int goal = -1;           // index into the goals given
  int expanded = 0;        // nodes taken off the open list
};

// With a SideOfHole the path must cross the hole's ray (cspace_grid.hpp) an even or odd number of
// times: the cheapest path on that side of the hole (the search runs over nodes x crossing parity).
struct SideOfHole {
  GridHole hole;
  int parity = 0;  // crossings modulo 2
};

struct SearchOptions {
  // A* (admissible, the optimal cost, when every goal cost is >= |node(goal) - target|_Sigma);
  // without, Dijkstra's.
  bool use_heuristic = true;
  // Nodes with a non-zero entry (empty, or one entry per cell) count as blocked too: the search
  // for another way round an obstacle (path_strategies.hpp).
  std::span<const std::uint8_t> also_blocked = {};
  std::optional<SideOfHole> side = std::nullopt;
  // Paths that cost more are not wanted: the search gives up once every remaining one would
  // (exact with the heuristic, which never overestimates).
  double max_cost = std::numeric_limits<double>::infinity();
};

// The cheapest path from any free source to any free goal, or nullopt when none is reachable
// (within options.max_cost).
std::optional<SearchPath> astarSearch(const CSpaceGrid& grid, std::span<const SearchEndpoint> sources,
                                      std::span<const SearchEndpoint> goals, const JointVector& target,
                                      const SearchOptions& options = {});

// How often a path through these grid nodes crosses the hole's ray, modulo 2.
int rayCrossingParity(const CSpaceGrid& grid, const GridHole& hole, std::span<const int> cells);

}  // namespace cyber::planner

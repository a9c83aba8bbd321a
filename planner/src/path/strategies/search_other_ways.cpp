// The search again round the other side of an obstacle (docs/algorithm.md section 2.6).
#include "path/strategies/path_strategies.hpp"

#include "path/astar_search.hpp"

namespace cyber::planner {
namespace {

// Every node within `radius` index steps of the path's cells, except those within `radius` of
// its two ends (the search must still leave the start and reach the goal): blocking this band
// makes the search find the way round the other side of an obstacle, when there is one.
std::vector<std::uint8_t> bandAround(const CSpaceGrid& grid, const std::vector<int>& cells, int radius) {
  std::vector<std::uint8_t> band(static_cast<size_t>(grid.cellCount()), 0);
  if (cells.empty()) return band;
  const auto dims = static_cast<size_t>(grid.dimensions());
  const GridIndex ends[2] = {grid.indices(cells.front()), grid.indices(cells.back())};
  auto near_end = [&](const GridIndex& idx) {
    for (const GridIndex& end : ends) {
      bool near = true;
      for (size_t d = 0; d < dims; ++d) near = near && std::abs(idx[d] - end[d]) <= radius;
      if (near) return true;
    }
    return false;
  };
  for (int cell : cells) {
    const GridIndex centre = grid.indices(cell);
    GridIndex lo{}, hi{};
    for (size_t d = 0; d < dims; ++d) {
      lo[d] = centre[d] - radius;
      hi[d] = centre[d] + radius;
    }
    grid.forEachInBox(lo, hi, [&](const GridIndex& idx, int c) {
      if (!near_end(idx)) band[static_cast<size_t>(c)] = 1;
    });
  }
  return band;
}

// When the fastest path is a detour (estimated well above the straight segment): the search again
// with the first path's band blocked or, where C-space has holes, on the other side of each.
void searchOtherWays(const CandidateInputs& in, CandidateList& list) {
  if (in.direct || list.empty()) return;
  const PathStrategySettings& s = in.settings();
  if (!(list.estimate(in, 0) > s.detour_ratio * in.straight_estimate_s)) return;
  auto add_search = [&](const std::optional<SearchPath>& found) {
    if (!found) return;
    std::vector<JointVector> around(in.polyline.begin(), in.polyline.begin() + in.fixed_head);
    for (int cell : found->cells) around.push_back(in.grid.node(cell));
    around.push_back(in.goal);
    addSmoothed(in, list, shortcutPolyline(in.world, around, in.fixed_head, shortcutClearance(in)));
  };
  // Without a hole the other way round is the search with the first path's band blocked; with
  // holes, the other side of each (the band also blocks a narrow corridor both ways share, leaving
  // a low pose with a piece held for example, and finds nothing).
  const std::vector<GridHole>& holes = in.grid.holes();
  if (holes.empty()) {
    const std::vector<std::uint8_t> band = bandAround(in.grid, in.first_cells, s.band_radius_nodes);
    add_search(astarSearch(in.grid, in.source_links, in.goal_links, in.goal, SearchOptions{.also_blocked = band}));
  }
  for (size_t h = 0; h < std::min(holes.size(), static_cast<size_t>(s.max_hole_sides)); ++h) {
    const SideOfHole other_side{holes[h], 1 - rayCrossingParity(in.grid, holes[h], in.first_cells)};
    add_search(astarSearch(in.grid, in.source_links, in.goal_links, in.goal,
                           SearchOptions{.side = other_side, .max_cost = s.max_side_cost * in.first_cost}));
  }
}

}  // namespace

CYBER_PATH_STRATEGY(search_other_ways, "other ways round", 30, searchOtherWays,
                    "the search finds one way round an obstacle; another may be faster");

}  // namespace cyber::planner

#include "path/astar_search.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "math/quaternary_heap.hpp"

namespace cyber::planner {
namespace {

// The open list's order as two integers, compared without branches (popping dominates the
// search): smallest f first; among equal f the deeper node (larger g), which expands fewer nodes;
// then the smaller node, so the order is total and the search's path does not depend on the heap.
// f and g are never negative, and the bits of non-negative IEEE numbers order as their values.
// g is needed only for the tie; the node's own cost is read from g[] when it is expanded.
struct OpenEntry {
  std::uint64_t f_bits;
  std::uint64_t tie;  // ~bits(float g) << 32 | node

  OpenEntry(double f, double g, int node)
      : f_bits(std::bit_cast<std::uint64_t>(f)),
        tie(static_cast<std::uint64_t>(~std::bit_cast<std::uint32_t>(static_cast<float>(g))) << 32 |
            static_cast<std::uint32_t>(node)) {}
  [[nodiscard]] double f() const { return std::bit_cast<double>(f_bits); }
  [[nodiscard]] int node() const { return static_cast<int>(tie & 0xffffffffU); }
};

struct EarlierEntry {
  // Bitwise, not short-circuit: the comparisons of a pop are unpredictable, and branches on them
  // cost more than doing both.
  bool operator()(const OpenEntry& a, const OpenEntry& b) const {
    return (a.f_bits < b.f_bits) | ((a.f_bits == b.f_bits) & (a.tie < b.tie));
  }
};

}  // namespace

std::optional<SearchPath> astarSearch(const CSpaceGrid& grid, std::span<const SearchEndpoint> sources,
                                      std::span<const SearchEndpoint> goals, const JointVector& target,
                                      const SearchOptions& options) {
  const bool use_heuristic = options.use_heuristic;
  const std::span<const std::uint8_t> also_blocked = options.also_blocked;
  const std::optional<SideOfHole>& side = options.side;
  // A search node is a grid cell and, with a side, the parity of ray crossings so far: node =
  // cell + parity * n.
  const int n = grid.cellCount();
  const int layers = side ? 2 : 1;
  const int goal_layer = side ? side->parity : 0;
  const int goal_node = layers * n;  // virtual node behind every goal connection
  const double inf = std::numeric_limits<double>::infinity();
  const int nj = grid.secondAxis().count;
  const int ni = grid.firstAxis().count;
  const JointVector metric = grid.metric();
  const double weight = grid.potentialWeight();

  // Goal nodes are few and close together: a bounding box of their indices makes the membership
  // test on every expansion cheap.
  int goal_i_lo = ni, goal_i_hi = -1, goal_j_lo = nj, goal_j_hi = -1;
  for (const SearchEndpoint& goal : goals) {
    if (goal.cell < 0 || goal.cell >= n || grid.blocked(goal.cell)) continue;
    goal_i_lo = std::min(goal_i_lo, grid.firstIndex(goal.cell));
    goal_i_hi = std::max(goal_i_hi, grid.firstIndex(goal.cell));
    goal_j_lo = std::min(goal_j_lo, grid.secondIndex(goal.cell));
    goal_j_hi = std::max(goal_j_hi, grid.secondIndex(goal.cell));
  }
  if (goal_i_hi < 0) return std::nullopt;
  // No goal in a source's region: nothing to search (the refused moves would otherwise expand
  // their whole region).
  bool reachable = false;
  for (const SearchEndpoint& source : sources) {
    if (source.cell < 0 || source.cell >= n || grid.blocked(source.cell)) continue;
    for (const SearchEndpoint& goal : goals) {
      if (goal.cell >= 0 && goal.cell < n && grid.region(goal.cell) == grid.region(source.cell)) reachable = true;
    }
  }
  if (!reachable) return std::nullopt;

  // In coordinates scaled by sqrt(metric), where |.|_Sigma is Euclidean.
  const double scale_e = std::sqrt(metric[0]), scale_a = std::sqrt(metric[1]);
  const double target_x = scale_e * target[0], target_y = scale_a * target[1];
  // The hole's ray: x = ray_x, y >= ray_y (crossesRay).
  const double ray_x =
      side ? scale_e * 0.5 * (grid.firstAxis().at(side->hole.i) + grid.firstAxis().at(side->hole.i + 1)) : 0.0;
  const double ray_y = side ? scale_a * grid.secondAxis().at(side->hole.j) : 0.0;
  auto length = [](double a, double b) { return std::sqrt(a * a + b * b); };  // std::hypot is slower
  // Of the node at indices (i, j) in `layer` (its cell's indices are known where it is pushed:
  // no divisions on the hot path).
  const GridAxis& first_axis = grid.firstAxis();
  const GridAxis& second_axis = grid.secondAxis();
  auto heuristic = [&](int i, int j, int layer) {
    if (!use_heuristic) return 0.0;
    const double q_e = first_axis.at(i), q_a = second_axis.at(j);
    if (layer == goal_layer) {
      const double d_e = q_e - target[0], d_a = q_a - target[1];
      return std::sqrt(metric[0] * d_e * d_e + metric[1] * d_a * d_a);
    }
    const double x = scale_e * q_e, y = scale_a * q_a;
    // On the wrong side a path must still cross the ray: the shortest way to the target through a
    // point of the ray. Its length is convex along the ray, so the unconstrained best point (the
    // straight line to the target or its mirror image) clamped to the ray. Consistent: a step
    // that crosses the ray is at least as long as the way through its crossing point.
    const double dx = x - ray_x, dx_target = target_x - ray_x;
    const double dx_far = dx * dx_target > 0.0 ? -dx_target : dx_target;
    const double denominator = dx - dx_far;
    const double y_best = std::abs(denominator) > 1e-12 ? y + (target_y - y) * dx / denominator : 0.5 * (y + target_y);
    const double y_ray = std::max(ray_y, y_best);
    return length(dx, y - y_ray) + length(dx_target, target_y - y_ray);
  };

  const auto nodes = static_cast<size_t>(goal_node) + 1;
  std::vector<double> g(nodes, inf);
  std::vector<int> parent(nodes, -1);
  std::vector<std::uint8_t> closed(nodes, 0);
  QuaternaryHeap<OpenEntry, EarlierEntry> open;
  open.reserve(1024);
  auto push = [&](int node, double cost, int from, double h) {
    if (cost >= g[static_cast<size_t>(node)]) return;
    g[static_cast<size_t>(node)] = cost;
    parent[static_cast<size_t>(node)] = from;
    open.push(OpenEntry(cost + h, cost, node));
  };
  for (const SearchEndpoint& source : sources) {
    if (source.cell < 0 || source.cell >= n || grid.blocked(source.cell)) continue;
    push(source.cell, source.cost, -1, heuristic(grid.firstIndex(source.cell), grid.secondIndex(source.cell), 0));
  }

  const double step_length[3][3] = {
      {grid.stepLength(1, 1), grid.stepLength(1, 0), grid.stepLength(1, 1)},
      {grid.stepLength(0, 1), 0.0, grid.stepLength(0, 1)},
      {grid.stepLength(1, 1), grid.stepLength(1, 0), grid.stepLength(1, 1)},
  };
  int expanded = 0;
  while (!open.empty()) {
    const OpenEntry entry = open.pop();
    const int top = entry.node();
    // An entry whose node has a cheaper one has a larger f, so the cheaper one came first and
    // closed the node (barring a tie in rounding, when the node is expanded at its cost in g[]).
    if (closed[static_cast<size_t>(top)] != 0) continue;
    if (entry.f() > options.max_cost) break;
    closed[static_cast<size_t>(top)] = 1;
    const double g_top = g[static_cast<size_t>(top)];
    ++expanded;
    if (top == goal_node) break;

    const int layer = top >= n ? 1 : 0;
    const int here = top - layer * n;
    const int i = grid.firstIndex(here);
    const int j = grid.secondIndex(here);
    if (layer == goal_layer && i >= goal_i_lo && i <= goal_i_hi && j >= goal_j_lo && j <= goal_j_hi) {
      for (const SearchEndpoint& goal : goals) {
        if (goal.cell == here) push(goal_node, g_top + goal.cost, top, 0.0);
      }
    }
    const double p_here = grid.potential(here);
    for (int di = -1; di <= 1; ++di) {
      const int a = i + di;
      if (a < 0 || a >= ni) continue;
      for (int dj = -1; dj <= 1; ++dj) {
        const int b = j + dj;
        if ((di == 0 && dj == 0) || b < 0 || b >= nj) continue;
        const int next_cell = grid.cell(a, b);
        const int next_layer = side && grid.crossesRay(side->hole, here, di, dj) ? 1 - layer : layer;
        const int next = next_cell + next_layer * n;
        if (closed[static_cast<size_t>(next)] != 0 || !grid.stepFree(here, di, dj)) continue;
        if (!also_blocked.empty() && also_blocked[static_cast<size_t>(next_cell)] != 0) continue;
        const double cost =
            g_top + step_length[di + 1][dj + 1] * (1.0 + weight * 0.5 * (p_here + grid.potential(next_cell)));
        if (cost >= g[static_cast<size_t>(next)]) continue;  // before the heuristic's square roots
        push(next, cost, top, heuristic(a, b, next_layer));
      }
    }
  }
  if (closed[static_cast<size_t>(goal_node)] == 0) return std::nullopt;

  SearchPath path;
  path.cost = g[static_cast<size_t>(goal_node)];
  path.expanded = expanded;
  const int last = parent[static_cast<size_t>(goal_node)];
  for (int node = last; node >= 0; node = parent[static_cast<size_t>(node)]) path.cells.push_back(node % n);
  std::reverse(path.cells.begin(), path.cells.end());
  // The endpoints actually used (the cheapest entry when a node is listed twice).
  const double goal_link = path.cost - g[static_cast<size_t>(last)];
  double best_goal_error = inf;
  for (size_t k = 0; k < goals.size(); ++k) {
    if (goals[k].cell != last % n) continue;
    const double error = std::abs(goals[k].cost - goal_link);
    if (error < best_goal_error) {
      best_goal_error = error;
      path.goal = static_cast<int>(k);
    }
  }
  const int first = path.cells.front();
  double best_source_error = inf;
  for (size_t k = 0; k < sources.size(); ++k) {
    if (sources[k].cell != first) continue;
    const double error = std::abs(sources[k].cost - g[static_cast<size_t>(first)]);
    if (error < best_source_error) {
      best_source_error = error;
      path.source = static_cast<int>(k);
    }
  }
  return path;
}

int rayCrossingParity(const CSpaceGrid& grid, const GridHole& hole, std::span<const int> cells) {
  int parity = 0;
  for (size_t k = 1; k < cells.size(); ++k) {
    const int di = grid.firstIndex(cells[k]) - grid.firstIndex(cells[k - 1]);
    const int dj = grid.secondIndex(cells[k]) - grid.secondIndex(cells[k - 1]);
    if (grid.crossesRay(hole, cells[k - 1], di, dj)) parity ^= 1;
  }
  return parity;
}

}  // namespace cyber::planner

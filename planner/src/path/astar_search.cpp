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

// Below this |dx - dx_far| the target and the node are level with the ray (in scaled units): the
// line between them crosses it nowhere in particular, and the midpoint's height serves.
constexpr double kLevelWithRay = 1e-12;

// Goal nodes are few and close together: a bounding box of their indices makes the membership
// test on every expansion cheap.
struct GoalBox {
  int dimensions;
  GridIndex lo;
  GridIndex hi;
  [[nodiscard]] bool contains(const GridIndex& idx) const {
    for (size_t d = 0; d < static_cast<size_t>(dimensions); ++d) {
      if (idx[d] < lo[d] || idx[d] > hi[d]) return false;
    }
    return true;
  }
};

// The box of the free goals; none when no goal is free.
std::optional<GoalBox> goalBox(const CSpaceGrid& grid, std::span<const SearchEndpoint> goals) {
  const int n = grid.cellCount();
  GoalBox box{grid.dimensions(), {}, {}};
  box.lo.fill(std::numeric_limits<int>::max());
  box.hi.fill(-1);
  bool any = false;
  for (const SearchEndpoint& goal : goals) {
    if (goal.cell < 0 || goal.cell >= n || grid.blocked(goal.cell)) continue;
    any = true;
    const GridIndex idx = grid.indices(goal.cell);
    for (size_t d = 0; d < static_cast<size_t>(grid.dimensions()); ++d) {
      box.lo[d] = std::min(box.lo[d], idx[d]);
      box.hi[d] = std::max(box.hi[d], idx[d]);
    }
  }
  if (!any) return std::nullopt;
  return box;
}

// Whether a goal lies in a free source's region: when none does there is nothing to search (the
// refused moves would otherwise expand their whole region).
bool goalInSourceRegion(const CSpaceGrid& grid, std::span<const SearchEndpoint> sources,
                        std::span<const SearchEndpoint> goals) {
  const int n = grid.cellCount();
  bool reachable = false;
  for (const SearchEndpoint& source : sources) {
    if (source.cell < 0 || source.cell >= n || grid.blocked(source.cell)) continue;
    for (const SearchEndpoint& goal : goals) {
      if (goal.cell >= 0 && goal.cell < n && grid.region(goal.cell) == grid.region(source.cell)) reachable = true;
    }
  }
  return reachable;
}

// The heuristic of a node at indices idx in `layer` (its cell's indices are known where it is
// pushed: no divisions on the hot path). Its own type, so that the search loop reads alone. A side
// of a hole (two joints only) needs the ray's geometry.
class SearchHeuristic {
 public:
  SearchHeuristic(const CSpaceGrid& grid, const JointVector& target, const SearchOptions& options)
      : grid_(grid),
        metric_(grid.metric()),
        target_(target),
        use_heuristic_(options.use_heuristic),
        goal_layer_(options.side ? options.side->parity : 0),
        scale_e_(options.side ? std::sqrt(metric_[0]) : 0.0),
        scale_a_(options.side ? std::sqrt(metric_[1]) : 0.0),
        target_x_(options.side ? scale_e_ * target[0] : 0.0),
        target_y_(options.side ? scale_a_ * target[1] : 0.0),
        ray_x_(options.side
                   ? scale_e_ * 0.5 *
                         (grid.firstAxis().at(options.side->hole.i) + grid.firstAxis().at(options.side->hole.i + 1))
                   : 0.0),
        ray_y_(options.side ? scale_a_ * grid.secondAxis().at(options.side->hole.j) : 0.0) {}

  double operator()(const GridIndex& idx, int layer) const {
    if (!use_heuristic_) return 0.0;
    if (layer == goal_layer_) {
      double sum = 0.0;
      for (int d = 0; d < grid_.dimensions(); ++d) {
        const double dq = grid_.axis(d).at(idx[static_cast<size_t>(d)]) - target_[d];
        sum += metric_[d] * dq * dq;
      }
      return std::sqrt(sum);
    }
    const double q_e = grid_.firstAxis().at(idx[0]), q_a = grid_.secondAxis().at(idx[1]);
    const double x = scale_e_ * q_e, y = scale_a_ * q_a;
    // On the wrong side a path must still cross the ray: the shortest way to the target through a
    // point of the ray. Its length is convex along the ray, so the unconstrained best point (the
    // straight line to the target or its mirror image) clamped to the ray. Consistent: a step
    // that crosses the ray is at least as long as the way through its crossing point.
    const double dx = x - ray_x_, dx_target = target_x_ - ray_x_;
    const double dx_far = dx * dx_target > 0.0 ? -dx_target : dx_target;
    const double denominator = dx - dx_far;
    const double y_best =
        std::abs(denominator) > kLevelWithRay ? y + (target_y_ - y) * dx / denominator : 0.5 * (y + target_y_);
    const double y_ray = std::max(ray_y_, y_best);
    return length(dx, y - y_ray) + length(dx_target, target_y_ - y_ray);
  }

 private:
  static double length(double a, double b) { return std::sqrt(a * a + b * b); }  // std::hypot is slower

  const CSpaceGrid& grid_;
  const JointVector metric_;
  const JointVector target_;
  const bool use_heuristic_;
  const int goal_layer_;
  // In coordinates scaled by sqrt(metric), where |.|_Sigma is Euclidean.
  const double scale_e_, scale_a_;
  const double target_x_, target_y_;
  // The hole's ray: x = ray_x, y >= ray_y (crossesRay).
  const double ray_x_, ray_y_;
};

// The search's state: costs, parents and the open list over nodes (a grid cell and, with a side,
// the parity of ray crossings so far: node = cell + parity * n, and a virtual goal node behind
// every goal connection). A type of its own so that one expansion is a function.
class AStar {
 public:
  AStar(const CSpaceGrid& grid, std::span<const SearchEndpoint> goals, const JointVector& target,
        const SearchOptions& options, GoalBox goal_box)
      : grid_(grid),
        goals_(goals),
        options_(options),
        heuristic_(grid, target, options),
        box_(goal_box),
        n_(grid.cellCount()),
        goal_layer_(options.side ? options.side->parity : 0),
        goal_node_((options.side ? 2 : 1) * n_),
        g_(static_cast<size_t>(goal_node_) + 1, std::numeric_limits<double>::infinity()),
        parent_(static_cast<size_t>(goal_node_) + 1, -1),
        closed_(static_cast<size_t>(goal_node_) + 1, 0) {
    open_.reserve(1024);
  }

  void pushSources(std::span<const SearchEndpoint> sources) {
    for (const SearchEndpoint& source : sources) {
      if (source.cell < 0 || source.cell >= n_ || grid_.blocked(source.cell)) continue;
      push(source.cell, source.cost, -1, heuristic_(grid_.indices(source.cell), 0));
    }
  }

  // Expands nodes until the goal node is closed, the open list is empty or max_cost is passed;
  // returns the number of nodes expanded.
  int run() {
    int expanded = 0;
    while (!open_.empty()) {
      const OpenEntry entry = open_.pop();
      const int top = entry.node();
      // An entry whose node has a cheaper one has a larger f, so the cheaper one came first and
      // closed the node (barring a tie in rounding, when the node is expanded at its cost in g[]).
      if (closed_[static_cast<size_t>(top)] != 0) continue;
      if (entry.f() > options_.max_cost) break;
      closed_[static_cast<size_t>(top)] = 1;
      ++expanded;
      if (top == goal_node_) break;
      expand(top);
    }
    return expanded;
  }

  // The cheapest path found, with the endpoints actually used; none when the goal was not reached.
  std::optional<SearchPath> path(std::span<const SearchEndpoint> sources, int expanded) const;

 private:
  void push(int node, double cost, int from, double h) {
    if (cost >= g_[static_cast<size_t>(node)]) return;
    g_[static_cast<size_t>(node)] = cost;
    parent_[static_cast<size_t>(node)] = from;
    open_.push(OpenEntry(cost + h, cost, node));
  }

  void expand(int top) {
    const double g_top = g_[static_cast<size_t>(top)];
    const std::optional<SideOfHole>& side = options_.side;
    const std::span<const std::uint8_t> also_blocked = options_.also_blocked;
    const double weight = grid_.potentialWeight();
    const int layer = top >= n_ ? 1 : 0;
    const int here = top - layer * n_;
    const GridIndex idx = grid_.indices(here);
    if (layer == goal_layer_ && box_.contains(idx)) {
      for (const SearchEndpoint& goal : goals_) {
        if (goal.cell == here) push(goal_node_, g_top + goal.cost, top, 0.0);
      }
    }
    const double p_here = grid_.potential(here);
    const std::vector<GridStep>& steps = grid_.steps();
    for (size_t k = 0; k < steps.size(); ++k) {
      const GridStep& step = steps[k];
      if (!grid_.inside(idx, step)) continue;
      const int next_cell = here + step.cell_delta;
      const int next_layer =
          side && grid_.crossesRay(side->hole, here, step.delta[0], step.delta[1]) ? 1 - layer : layer;
      const int next = next_cell + next_layer * n_;
      if (closed_[static_cast<size_t>(next)] != 0 || !grid_.stepFree(here, static_cast<int>(k))) continue;
      if (!also_blocked.empty() && also_blocked[static_cast<size_t>(next_cell)] != 0) continue;
      const double cost =
          g_top + grid_.stepLength(static_cast<int>(k)) * (1.0 + weight * 0.5 * (p_here + grid_.potential(next_cell)));
      if (cost >= g_[static_cast<size_t>(next)]) continue;  // before the heuristic's square roots
      GridIndex next_idx = idx;
      for (size_t d = 0; d < static_cast<size_t>(grid_.dimensions()); ++d) next_idx[d] += step.delta[d];
      push(next, cost, top, heuristic_(next_idx, next_layer));
    }
  }

  const CSpaceGrid& grid_;
  std::span<const SearchEndpoint> goals_;
  const SearchOptions& options_;
  const SearchHeuristic heuristic_;
  const GoalBox box_;
  const int n_;
  const int goal_layer_;
  const int goal_node_;
  std::vector<double> g_;
  std::vector<int> parent_;
  std::vector<std::uint8_t> closed_;
  QuaternaryHeap<OpenEntry, EarlierEntry> open_;
};

std::optional<SearchPath> AStar::path(std::span<const SearchEndpoint> sources, int expanded) const {
  if (closed_[static_cast<size_t>(goal_node_)] == 0) return std::nullopt;
  SearchPath path;
  path.cost = g_[static_cast<size_t>(goal_node_)];
  path.expanded = expanded;
  const int last = parent_[static_cast<size_t>(goal_node_)];
  for (int node = last; node >= 0; node = parent_[static_cast<size_t>(node)]) path.cells.push_back(node % n_);
  std::reverse(path.cells.begin(), path.cells.end());
  // The endpoints actually used (the cheapest entry when a node is listed twice).
  const double goal_link = path.cost - g_[static_cast<size_t>(last)];
  double best_goal_error = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < goals_.size(); ++k) {
    if (goals_[k].cell != last % n_) continue;
    const double error = std::abs(goals_[k].cost - goal_link);
    if (error < best_goal_error) {
      best_goal_error = error;
      path.goal = static_cast<int>(k);
    }
  }
  const int first = path.cells.front();
  double best_source_error = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < sources.size(); ++k) {
    if (sources[k].cell != first) continue;
    const double error = std::abs(sources[k].cost - g_[static_cast<size_t>(first)]);
    if (error < best_source_error) {
      best_source_error = error;
      path.source = static_cast<int>(k);
    }
  }
  return path;
}

}  // namespace

std::optional<SearchPath> astarSearch(const CSpaceGrid& grid, std::span<const SearchEndpoint> sources,
                                      std::span<const SearchEndpoint> goals, const JointVector& target,
                                      const SearchOptions& options) {
  const std::optional<GoalBox> box = goalBox(grid, goals);
  if (!box) return std::nullopt;
  if (!goalInSourceRegion(grid, sources, goals)) return std::nullopt;
  AStar search(grid, goals, target, options, *box);
  search.pushSources(sources);
  const int expanded = search.run();
  return search.path(sources, expanded);
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

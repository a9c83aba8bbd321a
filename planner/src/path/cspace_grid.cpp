#include "path/cspace_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "math/roundoff.hpp"
#include "path/path_clearance.hpp"

namespace cyber::planner {

GridAxis GridAxis::covering(const JointRange& range, double max_step, double inset) {
  GridAxis axis;
  const double span = range.max - range.min - 2.0 * inset;
  if (!(span > 0.0) || !(max_step > 0.0)) {
    axis.min = 0.5 * (range.min + range.max);
    axis.count = 1;
    axis.step = 1.0;
    return axis;
  }
  axis.min = range.min + inset;
  axis.count = static_cast<int>(std::ceil(span / max_step - kWholeCountSlack)) + 1;
  axis.step = span / (axis.count - 1);
  return axis;
}

namespace {

// The packed word's blocked bit: above every forward step's bit (4 in two dimensions, 13 in three).
std::uint16_t packedBlockedBit(int bytes) { return static_cast<std::uint16_t>(1U << (8 * bytes - 1)); }

// The steps to the 3^N - 1 neighbours in lexicographic order of their changes, with the strides
// of the cells, each forward step's bit and each step's opposite. Forward steps are numbered by
// the axis of their first change, then lexicographically: in two dimensions (+1, -1), (+1, 0),
// (+1, +1), (0, +1) are bits 0 to 3.
std::vector<GridStep> stepsOf(int dimensions, const std::array<int, kMaxJoints>& stride) {
  std::vector<GridStep> steps;
  int total = 1;
  for (int d = 0; d < dimensions; ++d) total *= 3;
  for (int code = 0; code < total; ++code) {
    GridStep step;
    int rest = code;
    bool zero = true;
    for (int d = dimensions - 1; d >= 0; --d) {
      step.delta[static_cast<size_t>(d)] = rest % 3 - 1;
      rest /= 3;
      zero = zero && step.delta[static_cast<size_t>(d)] == 0;
      step.cell_delta += step.delta[static_cast<size_t>(d)] * stride[static_cast<size_t>(d)];
    }
    if (!zero) steps.push_back(step);
  }
  const auto first_change = [&](const GridStep& step) {
    int d = 0;
    while (step.delta[static_cast<size_t>(d)] == 0) ++d;
    return d;
  };
  int bit = 0;
  for (int axis = 0; axis < dimensions; ++axis) {
    for (GridStep& step : steps) {
      if (first_change(step) == axis && step.delta[static_cast<size_t>(axis)] > 0) step.bit = bit++;
    }
  }
  for (GridStep& step : steps) {
    for (size_t k = 0; k < steps.size(); ++k) {
      if (steps[k].cell_delta == -step.cell_delta) step.reverse = static_cast<int>(k);
    }
  }
  return steps;
}

}  // namespace

void CSpaceGrid::setAxes(const PerJoint<GridAxis>& axes) {
  axes_ = axes;
  cell_count_ = 1;
  for (int d = dimensions() - 1; d >= 0; --d) {
    stride_[static_cast<size_t>(d)] = cell_count_;
    cell_count_ *= axes_[d].count;
  }
  steps_table_ = stepsOf(dimensions(), stride_);
  step_length_.clear();
  for (const GridStep& step : steps_table_) {
    double sum = 0.0;
    for (int d = 0; d < dimensions(); ++d) {
      const double dq = step.delta[static_cast<size_t>(d)] * axes_[d].step;
      sum += metric_[d] * dq * dq;
    }
    step_length_.push_back(std::sqrt(sum));
  }
}

CSpaceGrid::CSpaceGrid(const PerJoint<GridAxis>& axes, std::vector<std::uint8_t> blocked, const JointVector& metric,
                       const SearchSettings& search)
    : blocked_(std::move(blocked)), metric_(metric), potential_weight_(search.potential_weight) {
  setAxes(axes);
  blocked_.resize(static_cast<size_t>(cellCount()), 0);
  allowAllStepsBetweenFreeNodes();
  computePotential(search.potential_range);
  findHoles();
  labelRegions();
}

void CSpaceGrid::labelRegions() {
  // A flood fill over free steps from each unlabelled free node; steps are symmetric (stepFree).
  region_.assign(static_cast<size_t>(cellCount()), -1);
  std::vector<int> stack;
  const int step_count = static_cast<int>(steps_table_.size());
  for (int start = 0; start < cellCount(); ++start) {
    if (blocked(start) || region_[static_cast<size_t>(start)] >= 0) continue;
    region_[static_cast<size_t>(start)] = start;
    stack.assign(1, start);
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      const GridIndex idx = indices(c);
      for (int k = 0; k < step_count; ++k) {
        const GridStep& step = steps_table_[static_cast<size_t>(k)];
        if (!inside(idx, step)) continue;
        const int next = c + step.cell_delta;
        if (region_[static_cast<size_t>(next)] >= 0 || !stepFree(c, k)) continue;
        region_[static_cast<size_t>(next)] = start;
        stack.push_back(next);
      }
    }
  }
}

void CSpaceGrid::findHoles() {
  holes_.clear();
  if (dimensions() != 2) return;
  // Blocked regions, 8-connected, by a flood fill from each unlabelled blocked node.
  const int ni = axes_[0].count, nj = axes_[1].count;
  std::vector<int> label(static_cast<size_t>(cellCount()), -1);
  std::vector<int> stack;
  for (int start = 0; start < cellCount(); ++start) {
    if (!blocked(start) || label[static_cast<size_t>(start)] >= 0) continue;
    const int id = start;
    bool touches_edge = false;
    GridHole hole{-1, -1, 0};
    stack.assign(1, start);
    label[static_cast<size_t>(start)] = id;
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      ++hole.cells;
      const int i = firstIndex(c), j = secondIndex(c);
      touches_edge = touches_edge || i == 0 || j == 0 || i == ni - 1 || j == nj - 1;
      for (int di = -1; di <= 1; ++di) {
        for (int dj = -1; dj <= 1; ++dj) {
          const int a = i + di, b = j + dj;
          if (a < 0 || b < 0 || a >= ni || b >= nj) continue;
          const int next = cell(a, b);
          if (!blocked(next) || label[static_cast<size_t>(next)] >= 0) continue;
          label[static_cast<size_t>(next)] = id;
          stack.push_back(next);
        }
      }
    }
    if (touches_edge) continue;
    // The ray's foot: the highest pair of horizontally adjacent nodes of the region.
    for (int c = start; c < cellCount(); ++c) {
      const int i = firstIndex(c), j = secondIndex(c);
      if (label[static_cast<size_t>(c)] != id || i + 1 >= ni || label[static_cast<size_t>(cell(i + 1, j))] != id)
        continue;
      if (j > hole.j) hole = GridHole{i, j, hole.cells};
    }
    if (hole.i >= 0) holes_.push_back(hole);
  }
  std::sort(holes_.begin(), holes_.end(), [](const GridHole& a, const GridHole& b) { return a.cells > b.cells; });
}

void CSpaceGrid::allowAllStepsBetweenFreeNodes() {
  node_steps_.assign(static_cast<size_t>(cellCount()), 0);
  for (int c = 0; c < cellCount(); ++c) {
    if (blocked(c)) continue;
    const GridIndex idx = indices(c);
    for (const GridStep& step : steps_table_) {
      if (step.bit < 0 || !inside(idx, step) || blocked(c + step.cell_delta)) continue;
      node_steps_[static_cast<size_t>(c)] |= static_cast<std::uint16_t>(1U << step.bit);
    }
  }
}

PerJoint<GridAxis> CSpaceGrid::axesOf(const RobotModel& model) {
  const GridSettings& settings = model.planner.grid;
  PerJoint<GridAxis> axes;
  for (int j = 0; j < model.jointCount(); ++j)
    axes.push_back(GridAxis::covering(model.range(j), settings.step[j], settings.joint_limit_margin));
  return axes;
}

CSpaceGrid CSpaceGrid::build(const CollisionWorld& world, const RobotModel& model) {
  const PerJoint<GridAxis> axes = axesOf(model);
  const double clearance = model.clearance_m;
  const int n = axes.size();
  JointVector cell_size(n);
  for (int d = 0; d < n; ++d) cell_size[d] = axes[d].step;
  // Half a diagonal step can lose at most this much distance; farther nodes need no exact value.
  const double widest_margin = 0.5 * world.lipschitzBound(cell_size);
  CSpaceGrid grid;
  grid.metric_ = model.planner.metric;
  grid.setAxes(axes);
  const auto count = static_cast<size_t>(grid.cellCount());
  const double cutoff = clearance + widest_margin;
  // Along the last axis (neighbouring nodes in memory) the distance falls by at most one step's
  // Lipschitz bound per node: a node that a lower bound puts beyond the cutoff needs no query,
  // and any value beyond the cutoff decides the same below (docs/algorithm.md 2.1).
  JointVector last_step = JointVector::Zero(n);
  last_step[n - 1] = axes[n - 1].step;
  const double last_step_bound = world.lipschitzBound(last_step);
  const int last_count = axes[n - 1].count;
  std::vector<double> distance(count);
  std::vector<std::uint8_t> blocked(count, 0);
  for (size_t c = 0; c < count; ++c) {
    const bool row_start = static_cast<int>(c % static_cast<size_t>(last_count)) == 0;
    if (!row_start && distance[c - 1] - last_step_bound >= cutoff) {
      distance[c] = distance[c - 1] - last_step_bound;
      continue;
    }
    distance[c] = world.distance(grid.node(static_cast<int>(c)), cutoff).value;
    blocked[c] = distance[c] < clearance;
  }
  grid = CSpaceGrid(axes, std::move(blocked), model.planner.metric, model.planner.search);
  grid.clearance_m_ = clearance;
  // Steps near obstacles: keep only those a continuous check clears (the others its ends' distances
  // clear alone, with each step's bound, the same for every node).
  std::vector<double> step_bound(grid.steps_table_.size(), 0.0);
  for (size_t i = 0; i < grid.steps_table_.size(); ++i) {
    JointVector span(n);
    for (int d = 0; d < n; ++d) span[d] = std::abs(grid.steps_table_[i].delta[static_cast<size_t>(d)]) * axes[d].step;
    step_bound[i] = world.lipschitzBound(span);
  }
  for (int c = 0; c < grid.cellCount(); ++c) {
    if (grid.node_steps_[static_cast<size_t>(c)] == 0) continue;
    for (size_t i = 0; i < grid.steps_table_.size(); ++i) {
      const GridStep& step = grid.steps_table_[i];
      if (step.bit < 0 || ((grid.node_steps_[static_cast<size_t>(c)] >> step.bit) & 1U) == 0) continue;
      const int target = c + step.cell_delta;
      // checkStep's first test, without placing the step in the world.
      if (endsClearStep(distance[static_cast<size_t>(c)], distance[static_cast<size_t>(target)], step_bound[i],
                        clearance))
        continue;
      const StepCheck check = checkStep(world, grid.node(c), grid.node(target), clearance,
                                        distance[static_cast<size_t>(c)], distance[static_cast<size_t>(target)]);
      grid.checked_steps_ += check.evaluations > 0 ? 1 : 0;
      if (!check.clear) {
        grid.node_steps_[static_cast<size_t>(c)] &= static_cast<std::uint16_t>(~(1U << step.bit));
      }
    }
  }
  grid.labelRegions();  // the checks above may have split regions
  return grid;
}

std::vector<std::uint8_t> CSpaceGrid::packedNodes() const {
  const int bytes = bytesPerNode();
  const std::uint16_t blocked_bit = packedBlockedBit(bytes);
  std::vector<std::uint8_t> out(node_steps_.size() * static_cast<size_t>(bytes));
  for (size_t c = 0; c < node_steps_.size(); ++c) {
    std::uint16_t word = node_steps_[c];
    if (blocked_[c] != 0) word |= blocked_bit;
    for (int b = 0; b < bytes; ++b)
      out[c * static_cast<size_t>(bytes) + static_cast<size_t>(b)] = static_cast<std::uint8_t>(word >> (8 * b));
  }
  return out;
}

std::optional<CSpaceGrid> CSpaceGrid::fromPackedNodes(const PerJoint<GridAxis>& axes,
                                                      std::span<const std::uint8_t> nodes, const RobotModel& model,
                                                      int checked_steps) {
  // What the constructor derives from the blocked nodes, but the regions, which depend on the
  // steps: every step between free nodes, of which build() took the checked ones out.
  CSpaceGrid grid;
  grid.metric_ = model.planner.metric;
  grid.setAxes(axes);
  const int bytes = grid.bytesPerNode();
  const std::uint16_t blocked_bit = packedBlockedBit(bytes);
  const auto count = static_cast<size_t>(grid.cellCount());
  if (nodes.size() != count * static_cast<size_t>(bytes)) return std::nullopt;
  std::vector<std::uint16_t> words(count, 0);
  for (size_t c = 0; c < count; ++c) {
    for (int b = 0; b < bytes; ++b)
      words[c] |= static_cast<std::uint16_t>(nodes[c * static_cast<size_t>(bytes) + static_cast<size_t>(b)] << (8 * b));
  }
  grid.blocked_.resize(count);
  for (size_t c = 0; c < count; ++c) grid.blocked_[c] = (words[c] & blocked_bit) != 0 ? 1 : 0;
  grid.potential_weight_ = model.planner.search.potential_weight;
  grid.allowAllStepsBetweenFreeNodes();
  grid.computePotential(model.planner.search.potential_range);
  grid.findHoles();
  for (size_t c = 0; c < count; ++c) {
    const auto steps = static_cast<std::uint16_t>(words[c] & ~blocked_bit);
    if ((steps & ~grid.node_steps_[c]) != 0) return std::nullopt;
    grid.node_steps_[c] = steps;
  }
  grid.clearance_m_ = model.clearance_m;
  grid.checked_steps_ = checked_steps;
  grid.labelRegions();
  return grid;
}

int CSpaceGrid::blockedCount() const {
  return static_cast<int>(std::count(blocked_.begin(), blocked_.end(), std::uint8_t{1}));
}

int CSpaceGrid::lowerCorner(const JointVector& q) const {
  GridIndex idx{};
  for (int d = 0; d < dimensions(); ++d) {
    const GridAxis& axis = axes_[d];
    const double f = std::floor((q[d] - axis.min) / axis.step);
    idx[static_cast<size_t>(d)] = static_cast<int>(std::clamp(f, 0.0, static_cast<double>(axis.count - 1)));
  }
  return cellAt(idx);
}

void CSpaceGrid::computePotential(double range) {
  // Chamfer distance transform with the weighted lengths of the neighbour steps: a forward raster
  // pass relaxing the already-visited neighbours (the backward steps), then a backward pass
  // relaxing the forward ones.
  std::vector<double> dist(static_cast<size_t>(cellCount()), std::numeric_limits<double>::infinity());
  for (size_t c = 0; c < dist.size(); ++c) {
    if (blocked_[c] != 0) dist[c] = 0.0;
  }
  const auto relax = [&](int c, const GridIndex& idx, bool forward) {
    double& here = dist[static_cast<size_t>(c)];
    for (size_t k = 0; k < steps_table_.size(); ++k) {
      const GridStep& step = steps_table_[k];
      if ((step.cell_delta > 0) != forward || !inside(idx, step)) continue;
      here = std::min(here, dist[static_cast<size_t>(c + step.cell_delta)] + step_length_[k]);
    }
  };
  for (int c = 0; c < cellCount(); ++c) relax(c, indices(c), false);
  for (int c = cellCount() - 1; c >= 0; --c) relax(c, indices(c), true);
  potential_.assign(dist.size(), 0.0F);
  if (!(range > 0.0)) return;
  for (size_t c = 0; c < dist.size(); ++c) {
    // Quadratic fall-off: 1 at a blocked node, 0 with zero slope at the range.
    const double x = 1.0 - dist[c] / range;
    potential_[c] = x > 0.0 ? static_cast<float>(x * x) : 0.0F;
  }
}

}  // namespace cyber::planner

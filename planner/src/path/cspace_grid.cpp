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

CSpaceGrid::CSpaceGrid(GridAxis first, GridAxis second, std::vector<std::uint8_t> blocked, const JointVector& metric,
                       const SearchSettings& search)
    : first_(first),
      second_(second),
      blocked_(std::move(blocked)),
      metric_(metric),
      potential_weight_(search.potential_weight) {
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
  const int ni = first_.count, nj = second_.count;
  for (int start = 0; start < cellCount(); ++start) {
    if (blocked(start) || region_[static_cast<size_t>(start)] >= 0) continue;
    region_[static_cast<size_t>(start)] = start;
    stack.assign(1, start);
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      const int i = firstIndex(c), j = secondIndex(c);
      for (int di = -1; di <= 1; ++di) {
        for (int dj = -1; dj <= 1; ++dj) {
          const int a = i + di, b = j + dj;
          if ((di == 0 && dj == 0) || a < 0 || b < 0 || a >= ni || b >= nj) continue;
          const int next = cell(a, b);
          if (region_[static_cast<size_t>(next)] >= 0 || !stepFree(c, di, dj)) continue;
          region_[static_cast<size_t>(next)] = start;
          stack.push_back(next);
        }
      }
    }
  }
}

void CSpaceGrid::findHoles() {
  // Blocked regions, 8-connected, by a flood fill from each unlabelled blocked node.
  const int ni = first_.count, nj = second_.count;
  std::vector<int> label(static_cast<size_t>(cellCount()), -1);
  std::vector<int> stack;
  holes_.clear();
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
  steps_.assign(static_cast<size_t>(cellCount()), 0);
  for (int i = 0; i < first_.count; ++i) {
    for (int j = 0; j < second_.count; ++j) {
      const int c = cell(i, j);
      if (blocked(c)) continue;
      for (const auto& [di, dj] : {std::pair{1, -1}, std::pair{1, 0}, std::pair{1, 1}, std::pair{0, 1}}) {
        const int a = i + di, b = j + dj;
        if (a >= first_.count || b < 0 || b >= second_.count || blocked(cell(a, b))) continue;
        steps_[static_cast<size_t>(c)] |= static_cast<std::uint8_t>(1U << kStepBit[di + 1][dj + 1]);
      }
    }
  }
}

CSpaceGrid CSpaceGrid::build(const CollisionWorld& world, const RobotModel& model) {
  const GridSettings& settings = model.planner.grid;
  const GridAxis first = GridAxis::covering(model.range(0), settings.step[0], settings.joint_limit_margin);
  const GridAxis second = GridAxis::covering(model.range(1), settings.step[1], settings.joint_limit_margin);
  const double clearance = model.clearance_m;
  // Half a diagonal step can lose at most this much distance; farther nodes need no exact value.
  const double widest_margin = 0.5 * world.lipschitzBound(JointVector(first.step, second.step));
  const auto count = static_cast<size_t>(first.count) * static_cast<size_t>(second.count);
  std::vector<double> distance(count);
  std::vector<std::uint8_t> blocked(count, 0);
  for (int i = 0; i < first.count; ++i) {
    for (int j = 0; j < second.count; ++j) {
      const size_t c = static_cast<size_t>(i) * static_cast<size_t>(second.count) + static_cast<size_t>(j);
      distance[c] = world.distance(JointVector(first.at(i), second.at(j)), clearance + widest_margin).value;
      blocked[c] = distance[c] < clearance;
    }
  }
  CSpaceGrid grid(first, second, std::move(blocked), model.planner.metric, model.planner.search);
  grid.clearance_m_ = clearance;
  // Steps near obstacles: keep only those a continuous check clears.
  for (int i = 0; i < first.count; ++i) {
    for (int j = 0; j < second.count; ++j) {
      const int c = grid.cell(i, j);
      for (const auto& [di, dj] : {std::pair{1, -1}, std::pair{1, 0}, std::pair{1, 1}, std::pair{0, 1}}) {
        const int bit = kStepBit[di + 1][dj + 1];
        if (((grid.steps_[static_cast<size_t>(c)] >> bit) & 1U) == 0) continue;
        const int target = grid.cell(i + di, j + dj);
        const double margin =
            0.5 * world.lipschitzBound(JointVector(std::abs(di) * first.step, std::abs(dj) * second.step));
        if (std::min(distance[static_cast<size_t>(c)], distance[static_cast<size_t>(target)]) >= clearance + margin)
          continue;
        ++grid.checked_steps_;
        if (!checkSegment(world, grid.node(c), grid.node(target), clearance).clear) {
          grid.steps_[static_cast<size_t>(c)] &= static_cast<std::uint8_t>(~(1U << bit));
        }
      }
    }
  }
  grid.labelRegions();  // the checks above may have split regions
  return grid;
}

std::vector<std::uint8_t> CSpaceGrid::packedNodes() const {
  std::vector<std::uint8_t> out(steps_);
  for (size_t c = 0; c < out.size(); ++c) {
    if (blocked_[c] != 0) out[c] |= kPackedBlocked;
  }
  return out;
}

std::optional<CSpaceGrid> CSpaceGrid::fromPackedNodes(GridAxis first, GridAxis second,
                                                      std::span<const std::uint8_t> nodes, const RobotModel& model,
                                                      int checked_steps) {
  if (nodes.size() != static_cast<size_t>(first.count) * static_cast<size_t>(second.count)) return std::nullopt;
  std::vector<std::uint8_t> blocked(nodes.size());
  for (size_t c = 0; c < nodes.size(); ++c) blocked[c] = (nodes[c] & kPackedBlocked) != 0 ? 1 : 0;
  // What the constructor derives from the blocked nodes, but the regions, which depend on the
  // steps: every step between free nodes, of which build() took the checked ones out.
  CSpaceGrid grid;
  grid.first_ = first;
  grid.second_ = second;
  grid.blocked_ = std::move(blocked);
  grid.metric_ = model.planner.metric;
  grid.potential_weight_ = model.planner.search.potential_weight;
  grid.allowAllStepsBetweenFreeNodes();
  grid.computePotential(model.planner.search.potential_range);
  grid.findHoles();
  for (size_t c = 0; c < nodes.size(); ++c) {
    const auto steps = static_cast<std::uint8_t>(nodes[c] & ~kPackedBlocked);
    if ((steps & ~grid.steps_[c]) != 0) return std::nullopt;
    grid.steps_[c] = steps;
  }
  grid.clearance_m_ = model.clearance_m;
  grid.checked_steps_ = checked_steps;
  grid.labelRegions();
  return grid;
}

int CSpaceGrid::blockedCount() const {
  return static_cast<int>(std::count(blocked_.begin(), blocked_.end(), std::uint8_t{1}));
}

double CSpaceGrid::stepLength(int di, int dj) const {
  const double dt = di * first_.step;
  const double dth = dj * second_.step;
  return std::sqrt(metric_[0] * dt * dt + metric_[1] * dth * dth);
}

int CSpaceGrid::lowerCorner(const JointVector& q) const {
  auto index = [](const GridAxis& axis, double x) {
    const double f = std::floor((x - axis.min) / axis.step);
    return static_cast<int>(std::clamp(f, 0.0, static_cast<double>(axis.count - 1)));
  };
  return cell(index(first_, q[0]), index(second_, q[1]));
}

void CSpaceGrid::computePotential(double range) {
  // Chamfer distance transform with the weighted lengths of the 8 neighbour steps: a forward and
  // a backward raster pass, each relaxing the 4 already-visited neighbours.
  const int ni = first_.count;
  const int nj = second_.count;
  const double straight_i = stepLength(1, 0);
  const double straight_j = stepLength(0, 1);
  const double diagonal = stepLength(1, 1);
  std::vector<double> dist(static_cast<size_t>(cellCount()), std::numeric_limits<double>::infinity());
  for (size_t c = 0; c < dist.size(); ++c) {
    if (blocked_[c] != 0) dist[c] = 0.0;
  }
  auto relax = [&](int i, int j, int di, int dj, double w) {
    const int a = i + di;
    const int b = j + dj;
    if (a < 0 || a >= ni || b < 0 || b >= nj) return;
    double& here = dist[static_cast<size_t>(cell(i, j))];
    here = std::min(here, dist[static_cast<size_t>(cell(a, b))] + w);
  };
  for (int i = 0; i < ni; ++i) {
    for (int j = 0; j < nj; ++j) {
      relax(i, j, -1, -1, diagonal);
      relax(i, j, -1, 0, straight_i);
      relax(i, j, -1, 1, diagonal);
      relax(i, j, 0, -1, straight_j);
    }
  }
  for (int i = ni - 1; i >= 0; --i) {
    for (int j = nj - 1; j >= 0; --j) {
      relax(i, j, 1, 1, diagonal);
      relax(i, j, 1, 0, straight_i);
      relax(i, j, 1, -1, diagonal);
      relax(i, j, 0, 1, straight_j);
    }
  }
  potential_.assign(dist.size(), 0.0F);
  if (!(range > 0.0)) return;
  for (size_t c = 0; c < dist.size(); ++c) {
    // Quadratic fall-off: 1 at a blocked node, 0 with zero slope at the range.
    const double x = 1.0 - dist[c] / range;
    potential_[c] = x > 0.0 ? static_cast<float>(x * x) : 0.0F;
  }
}

}  // namespace cyber::planner

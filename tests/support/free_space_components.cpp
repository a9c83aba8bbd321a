#include "free_space_components.hpp"

#include <algorithm>
#include <cmath>

namespace cyber::test {

using planner::JointVector;

FreeSpaceComponents::FreeSpaceComponents(const planner::RobotModel& model, const planner::CollisionWorld& world,
                                         double step_m, int64_t max_nodes)
    : model_(model), world_(world), n_(model.jointCount()), min_(n_), step_(n_) {
  total_ = 1;
  for (int j = 0; j < n_; ++j) {
    const planner::JointRange r = model.range(j);
    const double rho = std::max(world.pointSpeedBound()[j], 1e-6);
    const double span = r.max - r.min;
    count_[j] = std::max<int64_t>(2, static_cast<int64_t>(std::ceil(span * rho / step_m)) + 1);
    min_[j] = r.min;
    step_[j] = span / static_cast<double>(count_[j] - 1);
    total_ *= count_[j];
    if (total_ > max_nodes) {
      too_fine_ = true;
      return;
    }
  }
  for (int j = n_ - 2; j >= 0; --j) stride_[j] = stride_[j + 1] * count_[j + 1];
  slack_m_ = world.lipschitzBound(0.5 * step_);
  state_.assign(static_cast<size_t>(total_), kUnknown);
  visited_.assign(static_cast<size_t>(total_), 0);
}

int64_t FreeSpaceComponents::nodeOf(const JointVector& q) const {
  int64_t node = 0;
  for (int j = 0; j < n_; ++j) {
    node += stride_[j] * std::clamp<int64_t>(std::llround((q[j] - min_[j]) / step_[j]), 0, count_[j] - 1);
  }
  return node;
}

bool FreeSpaceComponents::free(int64_t node) {
  uint8_t& s = state_[static_cast<size_t>(node)];
  if (s == kUnknown) {
    JointVector q(n_);
    int64_t rest = node;
    for (int j = 0; j < n_; ++j) {
      q[j] = min_[j] + static_cast<double>(rest / stride_[j]) * step_[j];
      rest %= stride_[j];
    }
    s = world_.distance(q, model_.clearance_m).value >= model_.clearance_m - slack_m_ ? kFree : kBlockedNode;
  }
  return s == kFree;
}

FreeSpaceComponents::Verdict FreeSpaceComponents::separated(const JointVector& a, const JointVector& b) {
  if (too_fine_) return Verdict::kTooFine;
  const int64_t from[2] = {nodeOf(a), nodeOf(b)};
  if (!free(from[0]) || !free(from[1])) return Verdict::kBlocked;
  if (from[0] == from[1]) return Verdict::kJoined;
  if (++query_ == 128) {  // the marks wrap: forget the old queries'
    std::fill(visited_.begin(), visited_.end(), uint8_t{0});
    query_ = 1;
  }
  const uint8_t mark[2] = {static_cast<uint8_t>(2 * query_), static_cast<uint8_t>(2 * query_ + 1)};
  std::vector<int64_t> frontier[2];
  for (int side = 0; side < 2; ++side) {
    visited_[static_cast<size_t>(from[side])] = mark[side];
    frontier[side].push_back(from[side]);
  }
  // Neighbour offsets: every joint -1, 0 or +1 step, not all 0.
  int neighbours = 1;
  for (int j = 0; j < n_; ++j) neighbours *= 3;
  int64_t coord[planner::kMaxJoints] = {0, 0, 0};
  for (;;) {
    // Grow the smaller fill: the first to run out is the smaller component, in its own time.
    const int side = frontier[0].size() <= frontier[1].size() ? 0 : 1;
    if (frontier[side].empty()) return Verdict::kSeparated;
    const int64_t c = frontier[side].back();
    frontier[side].pop_back();
    int64_t rest = c;
    for (int j = 0; j < n_; ++j) {
      coord[j] = rest / stride_[j];
      rest %= stride_[j];
    }
    for (int k = 0; k < neighbours; ++k) {
      int64_t next = 0;
      bool inside = true, same = true;
      for (int j = 0, code = k; j < n_; ++j, code /= 3) {
        const int64_t d = code % 3 - 1;
        same = same && d == 0;
        const int64_t x = coord[j] + d;
        inside = inside && x >= 0 && x < count_[j];
        next += stride_[j] * x;
      }
      if (same || !inside) continue;
      uint8_t& v = visited_[static_cast<size_t>(next)];
      if (v == mark[side]) continue;
      if (!free(next)) continue;
      if (v == mark[1 - side]) return Verdict::kJoined;
      v = mark[side];
      frontier[side].push_back(next);
    }
  }
}

bool provedSeparated(const planner::RobotModel& model, const planner::CollisionWorld& world,
                     const planner::JointVector& a, const planner::JointVector& b) {
  for (const double step_m : {0.02, 0.01, 0.005, 0.0025}) {
    FreeSpaceComponents components(model, world, step_m);
    if (components.separated(a, b) == FreeSpaceComponents::Verdict::kSeparated) return true;
  }
  return false;
}

}  // namespace cyber::test

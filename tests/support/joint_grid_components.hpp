#pragma once
// Connected components of an optimistic grid over a configuration space of any joint count: the
// flood-fill proof of free_space_components.hpp (two joints there) for the three-joint robot, whose
// refusals that file cannot prove yet. Header only, for the tests that prove refusals of every
// shipped robot (seeded and near-field moves); it goes when free_space_components takes N joints.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/robot_model.hpp"

namespace cyber::test {

// Nodes at most `step` apart per joint over the joint limits; a node is free when
// d >= clearance - L(h/2, ...), L the world's Lipschitz bound. Any continuous path keeping the
// clearance passes within half a step per joint of a chain of free nodes adjacent in every joint
// at once (3^N - 1 neighbours), so poses in different components cannot be joined by such a path.
class JointGridComponents {
 public:
  JointGridComponents(const planner::RobotModel& model, const planner::CollisionWorld& world, double step) {
    const int n = model.jointCount();
    planner::JointVector half(n);
    size_t total = 1;
    for (int j = 0; j < n; ++j) {
      const planner::JointRange r = model.range(j);
      min_.push_back(r.min);
      counts_.push_back(static_cast<int>(std::ceil((r.max - r.min) / step)) + 1);
      steps_.push_back((r.max - r.min) / (counts_.back() - 1));
      half[j] = 0.5 * steps_.back();
      total *= static_cast<size_t>(counts_.back());
    }
    const double slack = lipschitzBound(world, half);
    constexpr int kUnlabelled = -1;
    label_.assign(total, kBlocked);
    for (size_t i = 0; i < total; ++i) {
      if (world.distance(node(i), model.clearance_m).value >= model.clearance_m - slack) label_[i] = kUnlabelled;
    }
    std::vector<size_t> stack;
    std::vector<int> digits(static_cast<size_t>(n));
    for (size_t start = 0; start < total; ++start) {
      if (label_[start] != kUnlabelled) continue;
      label_[start] = count_;
      stack.push_back(start);
      while (!stack.empty()) {
        const size_t c = stack.back();
        stack.pop_back();
        const std::vector<int> at = coordinates(c);
        // Every offset in {-1, 0, 1}^N but the zero one.
        std::fill(digits.begin(), digits.end(), -1);
        for (;;) {
          bool inside = true, zero = true;
          size_t neighbour = 0;
          for (int j = 0; j < n; ++j) {
            const int a = at[static_cast<size_t>(j)] + digits[static_cast<size_t>(j)];
            inside = inside && a >= 0 && a < counts_[static_cast<size_t>(j)];
            zero = zero && digits[static_cast<size_t>(j)] == 0;
            neighbour = neighbour * static_cast<size_t>(counts_[static_cast<size_t>(j)]) + static_cast<size_t>(a);
          }
          if (inside && !zero && label_[neighbour] == kUnlabelled) {
            label_[neighbour] = count_;
            stack.push_back(neighbour);
          }
          int j = n - 1;
          while (j >= 0 && digits[static_cast<size_t>(j)] == 1) digits[static_cast<size_t>(j--)] = -1;
          if (j < 0) break;
          ++digits[static_cast<size_t>(j)];
        }
      }
      ++count_;
    }
  }

  // The component of the node nearest q: a pose within the limits that keeps the clearance is
  // always on a free node (kBlocked otherwise).
  [[nodiscard]] int of(const planner::JointVector& q) const {
    size_t i = 0;
    for (size_t j = 0; j < counts_.size(); ++j) {
      const int k = std::clamp(static_cast<int>(std::lround((q[static_cast<Eigen::Index>(j)] - min_[j]) / steps_[j])),
                               0, counts_[j] - 1);
      i = i * static_cast<size_t>(counts_[j]) + static_cast<size_t>(k);
    }
    return label_[i];
  }
  [[nodiscard]] int count() const { return count_; }

  static constexpr int kBlocked = -2;

 private:
  // Out of line: inlined beside the loop that fills `abs_dq`, g++ 12 warns (-Warray-bounds) of
  // Eigen's packet loads past a size it cannot know.
  [[gnu::noinline]] static double lipschitzBound(const planner::CollisionWorld& world,
                                                 const planner::JointVector& abs_dq) {
    return world.lipschitzBound(abs_dq);
  }
  [[nodiscard]] std::vector<int> coordinates(size_t i) const {
    std::vector<int> at(counts_.size());
    for (size_t j = counts_.size(); j-- > 0;) {
      at[j] = static_cast<int>(i % static_cast<size_t>(counts_[j]));
      i /= static_cast<size_t>(counts_[j]);
    }
    return at;
  }
  [[nodiscard]] planner::JointVector node(size_t i) const {
    const std::vector<int> at = coordinates(i);
    planner::JointVector q(static_cast<Eigen::Index>(at.size()));
    for (size_t j = 0; j < at.size(); ++j) q[static_cast<Eigen::Index>(j)] = min_[j] + at[j] * steps_[j];
    return q;
  }

  std::vector<double> min_, steps_;
  std::vector<int> counts_;
  int count_ = 0;
  std::vector<int> label_;
};

}  // namespace cyber::test

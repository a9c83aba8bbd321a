#include "free_space_components.hpp"

#include <algorithm>
#include <cmath>

namespace cyber::test {

using planner::JointVector;

FreeSpaceComponents::FreeSpaceComponents(const planner::RobotModel& model, const planner::CollisionWorld& world,
                                         double step)
    : range0_(model.range(0)), range1_(model.range(1)) {
  ni_ = static_cast<int>(std::ceil((range0_.max - range0_.min) / step)) + 1;
  nj_ = static_cast<int>(std::ceil((range1_.max - range1_.min) / step)) + 1;
  step0_ = (range0_.max - range0_.min) / (ni_ - 1);
  step1_ = (range1_.max - range1_.min) / (nj_ - 1);
  const double slack = world.lipschitzBound(JointVector{{0.5 * step0_, 0.5 * step1_}});
  constexpr int kUnlabelled = -1;
  label_.assign(static_cast<size_t>(ni_) * static_cast<size_t>(nj_), kBlocked);
  for (int i = 0; i < ni_; ++i) {
    for (int j = 0; j < nj_; ++j) {
      if (world.distance(node(i, j), model.clearance_m).value >= model.clearance_m - slack)
        label_[index(i, j)] = kUnlabelled;
    }
  }
  std::vector<int> stack;
  for (int start = 0; start < ni_ * nj_; ++start) {
    if (label_[static_cast<size_t>(start)] != kUnlabelled) continue;
    label_[static_cast<size_t>(start)] = count_;
    stack.push_back(start);
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      for (int di = -1; di <= 1; ++di) {
        for (int dj = -1; dj <= 1; ++dj) {
          const int a = c / nj_ + di, b = c % nj_ + dj;
          if (a < 0 || b < 0 || a >= ni_ || b >= nj_ || label_[index(a, b)] != kUnlabelled) continue;
          label_[index(a, b)] = count_;
          stack.push_back(static_cast<int>(index(a, b)));
        }
      }
    }
    ++count_;
  }
}

int FreeSpaceComponents::of(const JointVector& q) const {
  const int i = std::clamp(static_cast<int>(std::lround((q[0] - range0_.min) / step0_)), 0, ni_ - 1);
  const int j = std::clamp(static_cast<int>(std::lround((q[1] - range1_.min) / step1_)), 0, nj_ - 1);
  return label_[index(i, j)];
}

JointVector FreeSpaceComponents::node(int i, int j) const {
  return JointVector{{range0_.min + i * step0_, range1_.min + j * step1_}};
}

}  // namespace cyber::test

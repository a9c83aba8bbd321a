#include "path/joined_path.hpp"

#include <algorithm>

namespace cyber::planner {

PathPoint StraightPath::at(double s) const {
  PathPoint p;
  p.q = from_ + std::clamp(s, 0.0, length_) * direction_;
  p.dq_ds = direction_;
  p.d2q_ds2 = JointVector::Zero(direction_.size());
  return p;
}

PathPoint JoinedPath::at(double s) const {
  const double split = first_->length();
  return s < split ? first_->at(s) : second_->at(s - split);
}

Result<Trajectory> joinAtRest(const Trajectory& first, const Trajectory& second) {
  const std::vector<double>& s1 = first.sGrid();
  const std::vector<double>& b1 = first.bGrid();
  const std::vector<double>& s2 = second.sGrid();
  const std::vector<double>& b2 = second.bGrid();
  if (b1.empty() || b2.empty() || b1.back() != 0.0 || b2.front() != 0.0) {
    return Result<Trajectory>::failure(PlanStatus::kInvalidInput, "trajectories joined at rest must meet at rest");
  }
  auto path = std::make_shared<const JoinedPath>(first.sharedPath(), second.sharedPath());
  std::vector<double> s_grid(s1);
  std::vector<double> b_grid(b1);
  const double offset = first.path().length();
  for (size_t k = 1; k < s2.size(); ++k) {
    s_grid.push_back(offset + s2[k]);
    b_grid.push_back(b2[k]);
  }
  return Trajectory::create(std::move(path), first.drives(), std::move(s_grid), std::move(b_grid));
}

}  // namespace cyber::planner

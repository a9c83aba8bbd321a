#include "path/path_folds.hpp"

#include <algorithm>
#include <cmath>

namespace cyber::planner {

double sharpestTurnCosine(const GeometricPath& path, double spacing) {
  const double length = path.length();
  if (!(length > 0.0) || !(spacing > 0.0)) return 1.0;
  const int intervals = std::max(1, static_cast<int>(std::ceil(length / spacing)));
  double sharpest = 1.0;
  JointVector before = path.at(0.0).dq_ds;
  for (int i = 1; i <= intervals; ++i) {
    const JointVector after = path.at(std::min(length, i * spacing)).dq_ds;
    const double norms = before.norm() * after.norm();
    if (norms > 0.0) sharpest = std::min(sharpest, before.dot(after) / norms);
    before = after;
  }
  return sharpest;
}

}  // namespace cyber::planner

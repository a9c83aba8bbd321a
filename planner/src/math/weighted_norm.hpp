#pragma once
// The one C-space norm of algorithm.md section 2: |v|_Sigma = sqrt(v' Sigma v), Sigma diagonal
// (RobotModel::planner.metric).

#include <cmath>

#include "cyber/planner/types.hpp"

namespace cyber::planner {

// Poses closer than this in the weighted norm are the same pose (a zero-length move).
inline constexpr double kSamePoseWeighted = 1e-9;

// An empty v (no start velocity given) has norm 0.
inline double weightedNorm(const JointVector& v, const JointVector& metric) {
  double sum = 0.0;
  for (int j = 0; j < v.size(); ++j) sum += metric[j] * v[j] * v[j];
  return std::sqrt(sum);
}

}  // namespace cyber::planner

#pragma once
// The one C-space norm of algorithm.md section 2: |v|_Sigma = sqrt(v' Sigma v), Sigma diagonal
// (RobotModel::planner.metric).

#include <cmath>

#include "cyber/planner/types.hpp"

namespace cyber::planner {

// Poses closer than this in the weighted norm are the same pose (a zero-length move).
inline constexpr double kSamePoseWeighted = 1e-9;

inline double weightedNorm(const JointVector& v, const JointVector& metric) {
  return std::sqrt(metric[0] * v[0] * v[0] + metric[1] * v[1] * v[1]);
}

}  // namespace cyber::planner

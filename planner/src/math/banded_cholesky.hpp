#pragma once
// Cholesky factorisation H = L L' of a symmetric positive definite band matrix with lower
// bandwidth w, stored by rows: O(n w^2) to factor, O(n w) per solve, nothing dense.

#include <Eigen/Core>

namespace cyber::planner {

// A pivot below this share of its diagonal entry has lost every digit to cancellation (a double
// keeps about 16): the factor would be singular to roundoff.
inline constexpr double kMinPivot = 1e-12;

class BandedCholesky {
 public:
  // Clears to an n x n zero matrix of lower bandwidth w (entries (i, j) with i - w <= j <= i).
  void reset(Eigen::Index n, int bandwidth);
  [[nodiscard]] Eigen::Index size() const { return n_; }
  [[nodiscard]] int bandwidth() const { return w_; }
  // Adds to H(i, j) (and H(j, i)); |i - j| must be within the bandwidth.
  void add(Eigen::Index i, Eigen::Index j, double value);
  [[nodiscard]] double entry(Eigen::Index i, Eigen::Index j) const;

  // Factors in place. A pivot below `min_pivot` times its diagonal entry (or not positive) is
  // replaced by that floor, so the result is always a usable preconditioner; returns the number
  // of pivots replaced.
  int factor(double min_pivot = kMinPivot);
  // x <- L^{-1} x and x <- L^{-T} x with the factor (x of size(); a vector or a contiguous
  // segment of one).
  void solveLower(Eigen::Ref<Eigen::VectorXd> x) const;
  void solveUpper(Eigen::Ref<Eigen::VectorXd> x) const;

 private:
  double& at(Eigen::Index i, Eigen::Index j) { return band_(i, j - i + w_); }
  [[nodiscard]] double at(Eigen::Index i, Eigen::Index j) const { return band_(i, j - i + w_); }
  Eigen::Index n_ = 0;
  int w_ = 0;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> band_;  // n x (w + 1)
};

}  // namespace cyber::planner

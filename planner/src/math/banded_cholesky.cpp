#include "math/banded_cholesky.hpp"

#include <algorithm>
#include <cmath>

namespace cyber::planner {

void BandedCholesky::reset(Eigen::Index n, int bandwidth) {
  n_ = n;
  w_ = bandwidth;
  band_.resize(n, bandwidth + 1);
  band_.setZero();
}

void BandedCholesky::add(Eigen::Index i, Eigen::Index j, double value) {
  if (j > i) std::swap(i, j);
  at(i, j) += value;
}

double BandedCholesky::entry(Eigen::Index i, Eigen::Index j) const {
  if (j > i) std::swap(i, j);
  return i - j > w_ ? 0.0 : at(i, j);
}

namespace {

// Near the smallest normal double: a zero diagonal still gets a positive floor, and its square
// root and reciprocal stay finite.
constexpr double kTinyPivot = 1e-300;

}  // namespace

int BandedCholesky::factor(double min_pivot) {
  int replaced = 0;
  for (Eigen::Index j = 0; j < n_; ++j) {
    const Eigen::Index first = std::max<Eigen::Index>(0, j - w_);
    const double original = at(j, j);
    double pivot = original;
    for (Eigen::Index k = first; k < j; ++k) pivot -= at(j, k) * at(j, k);
    const double floor = min_pivot * std::max(std::abs(original), kTinyPivot);
    if (!(pivot > floor)) {
      pivot = std::max(floor, kTinyPivot);
      ++replaced;
    }
    const double diag = std::sqrt(pivot);
    at(j, j) = diag;
    const Eigen::Index last = std::min<Eigen::Index>(n_ - 1, j + w_);
    for (Eigen::Index i = j + 1; i <= last; ++i) {
      double v = at(i, j);
      for (Eigen::Index k = std::max<Eigen::Index>(0, i - w_); k < j; ++k) v -= at(i, k) * at(j, k);
      at(i, j) = v / diag;
    }
  }
  return replaced;
}

void BandedCholesky::solveLower(Eigen::Ref<Eigen::VectorXd> x) const {
  for (Eigen::Index i = 0; i < n_; ++i) {
    double v = x[i];
    for (Eigen::Index k = std::max<Eigen::Index>(0, i - w_); k < i; ++k) v -= at(i, k) * x[k];
    x[i] = v / at(i, i);
  }
}

void BandedCholesky::solveUpper(Eigen::Ref<Eigen::VectorXd> x) const {
  // Column-oriented: once x_i is final, remove its contribution from the rows above (row i of
  // L is contiguous in the band storage).
  for (Eigen::Index i = n_ - 1; i >= 0; --i) {
    const double xi = x[i] / at(i, i);
    x[i] = xi;
    for (Eigen::Index k = std::max<Eigen::Index>(0, i - w_); k < i; ++k) x[k] -= at(i, k) * xi;
  }
}

}  // namespace cyber::planner

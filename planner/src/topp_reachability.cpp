#include "cyber/planner/topp_reachability.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace cyber::planner::topp {
namespace {

constexpr int kBisections = 48;
constexpr double kMaxSpeed = 1e3;        // upper bound on c = sqrt(b) searched for [path units/s]
constexpr double kRowTolerance = 1e-11;  // rows are normalised to order one
constexpr int kMaxCandidates = 64;

// Largest c in [0, c_max] with pred(c) true, assuming pred holds on an interval starting at 0.
template <class Pred>
double largestTrue(Pred pred, double c_max, int bisections = kBisections) {
  if (pred(c_max)) return c_max;
  double lo = 0.0;
  double hi = c_max;
  for (int i = 0; i < bisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    (pred(mid) ? lo : hi) = mid;
  }
  return lo;
}

// A row of interval k as a quadratic q(t) = A t^2 + B t + C in the free end's speed t.
struct Quadratic {
  double a, b, c, lo, hi;
  [[nodiscard]] double at(double t) const { return (a * t + b) * t + c; }
};

// Appends the real roots of a t^2 + b t + c in [0, t_max].
void addRoots(double a, double b, double c, double t_max, std::array<double, kMaxCandidates>& out, int& count) {
  auto push = [&](double t) {
    if (t >= 0.0 && t <= t_max && count < kMaxCandidates) out[static_cast<size_t>(count++)] = t;
  };
  if (std::abs(a) < 1e-300) {
    if (b != 0.0) push(-c / b);
    return;
  }
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  push(q / a);
  if (q != 0.0) push(c / q);
}

// Rows of interval k in the speed of one end with the other end's speed fixed. `forward`: the
// free speed is c_{k+1} (given c_k = fixed), else c_k (given c_{k+1} = fixed).
int rowsAsQuadratics(const Problem& problem, int k, double fixed, bool forward, std::array<Quadratic, kMaxCandidates>& q) {
  const double inv = 1.0 / (2.0 * problem.ds(k));
  const int begin = problem.row_begin[static_cast<size_t>(k)];
  const int end = problem.row_begin[static_cast<size_t>(k) + 1];
  int count = 0;
  for (int i = begin; i < end && count < kMaxCandidates; ++i) {
    const LinearRow& r = problem.rows[static_cast<size_t>(i)];
    const bool left = r.node == k;
    const double f2 = fixed * fixed;
    Quadratic out{0.0, 0.0, 0.0, r.lo, r.hi};
    // value = alpha (c1^2 - c0^2) inv + beta c_node^2 + gamma c_node
    if (forward) {
      out.a = r.alpha * inv + (left ? 0.0 : r.beta);
      out.b = left ? 0.0 : r.gamma;
      out.c = -r.alpha * f2 * inv + (left ? r.beta * f2 + r.gamma * fixed : 0.0);
    } else {
      out.a = -r.alpha * inv + (left ? r.beta : 0.0);
      out.b = left ? r.gamma : 0.0;
      out.c = r.alpha * f2 * inv + (left ? 0.0 : r.beta * f2 + r.gamma * fixed);
    }
    q[static_cast<size_t>(count++)] = out;
  }
  return count;
}

// Largest t in [0, t_max] where every quadratic is within its bounds; -1 when none is. The
// feasible set is a finite union of closed intervals whose ends are roots or 0 or t_max.
double largestFeasible(const std::array<Quadratic, kMaxCandidates>& q, int rows, double t_max) {
  std::array<double, kMaxCandidates> candidates{};
  int count = 0;
  candidates[static_cast<size_t>(count++)] = t_max;
  candidates[static_cast<size_t>(count++)] = 0.0;
  for (int i = 0; i < rows; ++i) {
    const Quadratic& r = q[static_cast<size_t>(i)];
    addRoots(r.a, r.b, r.c - r.hi, t_max, candidates, count);
    if (std::isfinite(r.lo)) addRoots(r.a, r.b, r.c - r.lo, t_max, candidates, count);
  }
  std::sort(candidates.begin(), candidates.begin() + count, std::greater<>());
  for (int i = 0; i < count; ++i) {
    const double t = candidates[static_cast<size_t>(i)];
    bool ok = true;
    for (int j = 0; j < rows && ok; ++j) {
      const Quadratic& r = q[static_cast<size_t>(j)];
      const double v = r.at(t);
      ok = v <= r.hi + kRowTolerance && v >= r.lo - kRowTolerance;
    }
    if (ok) return t;
  }
  return -1.0;
}

}  // namespace

AccelInterval admissibleAcceleration(const Problem& problem, int interval, int node, double b) {
  const double c = std::sqrt(std::max(0.0, b));
  AccelInterval out{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  const int begin = problem.row_begin[static_cast<size_t>(interval)];
  const int end = problem.row_begin[static_cast<size_t>(interval) + 1];
  for (int i = begin; i < end; ++i) {
    const LinearRow& row = problem.rows[static_cast<size_t>(i)];
    if (row.node != node) continue;
    const double rest = row.beta * b + row.gamma * c;
    if (row.alpha > 0.0) {
      out.lo = std::max(out.lo, (row.lo - rest) / row.alpha);
      out.hi = std::min(out.hi, (row.hi - rest) / row.alpha);
    } else if (row.alpha < 0.0) {
      out.lo = std::max(out.lo, (row.hi - rest) / row.alpha);
      out.hi = std::min(out.hi, (row.lo - rest) / row.alpha);
    } else if (rest < row.lo || rest > row.hi) {
      return AccelInterval{1.0, -1.0};
    }
  }
  return out;
}

double fastestNextSpeed(const Problem& problem, int interval, double c_now, double c_next_max) {
  std::array<Quadratic, kMaxCandidates> q{};
  const int rows = rowsAsQuadratics(problem, interval, c_now, true, q);
  return largestFeasible(q, rows, c_next_max);
}

ReachabilityResult forwardBackward(const Problem& problem, std::vector<double>& b, std::vector<double>& controllable) {
  ReachabilityResult result;
  const int k_points = problem.gridPoints();
  b.assign(static_cast<size_t>(k_points), 0.0);
  controllable.assign(static_cast<size_t>(k_points), 0.0);
  const int last = k_points - 1;

  controllable[static_cast<size_t>(last)] = problem.b_end;
  for (int k = last - 1; k >= 0; --k) {
    const double ds = problem.ds(k);
    const double next = controllable[static_cast<size_t>(k) + 1];
    const double c_next = std::sqrt(next);
    // First the cheap bound from the left-end rows alone (a linear interval in a)...
    auto stoppable_left = [&](double c) {
      const AccelInterval a = admissibleAcceleration(problem, k, k, c * c);
      return !a.empty() && c * c + 2.0 * a.lo * ds <= next * (1.0 + 1e-12) + 1e-15;
    };
    // ...then all rows: some reachable c_{k+1} <= sqrt(C_{k+1}) must exist.
    auto stoppable = [&](double c) { return fastestNextSpeed(problem, k, c, c_next) >= 0.0; };
    if (!stoppable(0.0)) {
      char text[160];
      std::snprintf(text, sizeof text, "the path cannot be followed even slowly near s = %.4f",
                    problem.s[static_cast<size_t>(k)]);
      result.status = ReachabilityStatus::kNotControllable;
      result.reason = text;
      return result;
    }
    const double c_left = largestTrue(stoppable_left, kMaxSpeed);
    const double c = stoppable(c_left) ? c_left : largestTrue(stoppable, c_left, 40);
    controllable[static_cast<size_t>(k)] = c * c;
  }
  result.controllable_start_b = controllable[0];

  if (problem.b_start > controllable[0] * (1.0 + 1e-9) + 1e-12) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "start speed^2 b = %.6g along the path cannot be brought to rest within the limits "
                  "(largest controllable b = %.6g)",
                  problem.b_start, controllable[0]);
    result.status = ReachabilityStatus::kStartNotControllable;
    result.reason = text;
    return result;
  }
  b[0] = problem.b_start;
  double c = std::sqrt(problem.b_start);
  for (int k = 0; k < last; ++k) {
    const double c_max = std::sqrt(controllable[static_cast<size_t>(k) + 1]);
    double c_next = fastestNextSpeed(problem, k, c, c_max);
    if (c_next < 0.0) c_next = c_max;  // roundoff at the controllable boundary; the optimiser repairs it
    b[static_cast<size_t>(k) + 1] = c_next * c_next;
    c = c_next;
  }
  b[static_cast<size_t>(last)] = problem.b_end;
  return result;
}

}  // namespace cyber::planner::topp

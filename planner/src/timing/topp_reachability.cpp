#include "timing/topp_reachability.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace cyber::planner::topp {
namespace {

constexpr double kRowTolerance = 1e-11;  // rows are normalised to order one
constexpr int kMaxCandidates = 64;
// A coefficient this small is a polynomial of lower degree: dividing by it would overflow.
constexpr double kNegligibleCoefficient = 1e-300;
constexpr double kDiscriminantFactor = 4.0;  // b^2 - 4 a c
// b values (the problem's units) that differ by less than this share plus this much are equal to
// roundoff: a start on C_0's edge is controllable.
constexpr double kRelativeRoundoff = 1e-9;
constexpr double kAbsoluteRoundoff = 1e-12;
// The search near a guess starts this share of it away (at least that share of kSmallestSpeed) and
// grows its step this many times each try: the controllable speed varies little between nodes.
constexpr double kFirstStepShare = 1e-4;
constexpr double kSmallestSpeed = 1e-3;
constexpr double kStepGrowth = 4.0;

// A row of interval k as a quadratic q(t) = A t^2 + B t + C in the free end's speed t.
struct Quadratic {
  double a, b, c, lo, hi;
  [[nodiscard]] double at(double t) const { return (a * t + b) * t + c; }
};

// Appends the real roots of a t^2 + b t + c in [0, t_max].
void addRoots(double a, double b, double c, double t_max, std::array<double, 4>& out, int& count) {
  auto push = [&](double t) {
    if (t >= 0.0 && t <= t_max) out[static_cast<size_t>(count++)] = t;
  };
  if (std::abs(a) < kNegligibleCoefficient) {
    if (b != 0.0) push(-c / b);
    return;
  }
  const double disc = b * b - kDiscriminantFactor * a * c;
  if (disc < 0.0) return;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  push(q / a);
  if (q != 0.0) push(c / q);
}

// A row of interval k, value = alpha (c1^2 - c0^2) / (2 ds) + beta ((1-w) c0^2 + w c1^2) +
// gamma ((1-w) c0 + w c1), as a quadratic in either end's speed: c1^2 a_next + c1 b_next +
// c0^2 a_now + c0 b_now. The backward pass asks many questions of one interval; the forms are
// made once for all of them.
struct RowForm {
  double a_next, b_next, a_now, b_now, lo, hi;
};
using IntervalForms = std::array<RowForm, kMaxCandidates>;

int intervalForms(const Problem& problem, int k, IntervalForms& forms) {
  const double inv = 1.0 / (2.0 * problem.ds(k));
  const int begin = problem.row_begin[static_cast<size_t>(k)];
  const int end = problem.row_begin[static_cast<size_t>(k) + 1];
  int count = 0;
  for (int i = begin; i < end && count < kMaxCandidates; ++i) {
    const LinearRow& r = problem.rows[static_cast<size_t>(i)];
    const double w = r.at;
    forms[static_cast<size_t>(count++)] = {r.alpha * inv + r.beta * w, r.gamma * w, -r.alpha * inv + r.beta * (1.0 - w),
                                           r.gamma * (1.0 - w),        r.lo,        r.hi};
  }
  return count;
}

// The rows in the speed of one end with the other end's speed fixed. `forward`: the free speed
// is c_{k+1} (given c_k = fixed), else c_k (given c_{k+1} = fixed).
void rowsAsQuadratics(const IntervalForms& forms, int rows, double fixed, bool forward,
                      std::array<Quadratic, kMaxCandidates>& q) {
  const double f2 = fixed * fixed;
  for (int i = 0; i < rows; ++i) {
    const RowForm& r = forms[static_cast<size_t>(i)];
    q[static_cast<size_t>(i)] = forward ? Quadratic{r.a_next, r.b_next, r.a_now * f2 + r.b_now * fixed, r.lo, r.hi}
                                        : Quadratic{r.a_now, r.b_now, r.a_next * f2 + r.b_next * fixed, r.lo, r.hi};
  }
}

[[nodiscard]] bool withinBounds(const Quadratic& r, double t) {
  const double v = r.at(t);
  return v <= r.hi + kRowTolerance && v >= r.lo - kRowTolerance;
}

// The speeds in [0, t_max] where a row meets one of its bounds (q = hi, or q = lo when finite).
int boundaryRoots(const Quadratic& r, double t_max, std::array<double, 4>& roots) {
  int count = 0;
  addRoots(r.a, r.b, r.c - r.hi, t_max, roots, count);
  if (std::isfinite(r.lo)) addRoots(r.a, r.b, r.c - r.lo, t_max, roots, count);
  return count;
}

// Largest t' in [0, t] where one row is within its bounds, -1 when none is. Its feasible set is
// at most two closed intervals, whose right ends are roots of q = hi or q = lo, or t itself.
double largestWithinBelow(const Quadratic& r, double t) {
  std::array<double, 4> ends{};
  const int count = boundaryRoots(r, t, ends);
  double best = withinBounds(r, 0.0) ? 0.0 : -1.0;
  for (int i = 0; i < count; ++i) {
    const double end = ends[static_cast<size_t>(i)];
    if (end > best && withinBounds(r, end)) best = end;
  }
  return best;
}

// Largest t in [0, t_max] where every quadratic is within its bounds; -1 when none is. Descends
// from t_max: each row that is violated moves t down to its own largest feasible point below t.
// The answer is feasible for every row, so no step passes it; t falls strictly at each move and
// lands only on one of finitely many roots, so the descent ends, usually after a move or two.
double largestFeasible(const std::array<Quadratic, kMaxCandidates>& q, int rows, double t_max) {
  double t = t_max;
  int satisfied = 0;  // rows in a row, cyclically, found within bounds at the current t
  for (int j = 0; satisfied < rows; j = (j + 1) % rows) {
    const Quadratic& r = q[static_cast<size_t>(j)];
    if (withinBounds(r, t)) {
      ++satisfied;
      continue;
    }
    t = largestWithinBelow(r, t);
    if (t < 0.0) return -1.0;
    satisfied = 1;
  }
  return t;
}

// Largest speed in [0, cap] at the free end (`forward`: c_{k+1}, else c_k) that every row of the
// interval admits with the other end's speed fixed; -1 when none does.
double largestFreeSpeed(const IntervalForms& forms, int rows, double fixed, bool forward, double cap) {
  std::array<Quadratic, kMaxCandidates> q;
  rowsAsQuadratics(forms, rows, fixed, forward, q);
  return largestFeasible(q, rows, cap);
}

// Some c_{k+1} in [0, c_next_max] admits every row of the interval with c_k = c_now.
bool reachable(const IntervalForms& forms, int rows, double c_now, double c_next_max) {
  return largestFreeSpeed(forms, rows, c_now, true, c_next_max) >= 0.0;
}

// Bisects [lo, hi] (pred(lo) true, pred(hi) false) to a relative width of `tolerance`
// (Problem::controllable_tolerance): C_k is a cap for the forward pass, and the optimiser absorbs
// anything below that.
template <class Pred>
double bisect(Pred pred, double lo, double hi, double tolerance) {
  while (hi - lo > tolerance * hi) {
    const double mid = 0.5 * (lo + hi);
    (pred(mid) ? lo : hi) = mid;
  }
  return lo;
}

// Largest c in [known, c_max] with pred(c) true, pred(known) true, searched near `guess`: the
// controllable speed varies little from node to node, so a geometric search from the guess
// brackets it in a few steps (assumes pred holds on an interval).
template <class Pred>
double largestTrueNear(Pred pred, double known, double guess, double c_max, double tolerance) {
  guess = std::clamp(guess, known, c_max);
  double step = kFirstStepShare * std::max(guess, kSmallestSpeed);
  if (guess > known && !pred(guess)) {
    double hi = guess;
    for (double c = guess - step; c > known; step *= kStepGrowth, c = guess - step) {
      if (pred(c)) return bisect(pred, c, hi, tolerance);
      hi = c;
    }
    return bisect(pred, known, hi, tolerance);
  }
  double lo = guess;
  for (double c = lo + step; c < c_max; step *= kStepGrowth, c = lo + step) {
    if (!pred(c)) return bisect(pred, lo, c, tolerance);
    lo = c;
  }
  return pred(c_max) ? c_max : bisect(pred, lo, c_max, tolerance);
}

// Largest c in [known, cap] such that every speed from `known` to c is one at which the rows at
// interval k's left end alone admit an acceleration that brakes to at most `next` (a speed
// squared) by its right end; `known` itself when it is not one. With b = c^2 each row bounds a by
// a quadratic in c over alpha, so "the lowest admitted a brakes enough" and "the admitted a are
// not empty" are quadratic conditions in c, and the answer is the first root above `known` at
// which one of them stops holding: exact, and one pass over the rows. Above that root the
// conditions can hold again (two joints' terms in c^2 can cancel far above any reachable speed);
// those speeds are not connected to `known`.
double leftStoppableAbove(const Problem& problem, int k, double next, double known, double cap) {
  const double inv = 1.0 / (2.0 * problem.ds(k));
  const int begin = problem.row_begin[static_cast<size_t>(k)];
  const int end = problem.row_begin[static_cast<size_t>(k) + 1];
  // a >= (bound - beta c^2 - gamma c) / alpha, and a <= the same with the other bound.
  struct Bound {
    double c2, c1, c0;
  };
  std::array<Bound, kMaxCandidates> lower{}, upper{};
  int lowers = 0, uppers = 0;
  double top = cap;
  bool feasible = true;
  auto limit = [&](const Quadratic& r) {
    if (!withinBounds(r, known)) feasible = false;
    std::array<double, 4> roots{};
    const int count = boundaryRoots(r, top, roots);
    for (int i = 0; i < count; ++i) {
      if (roots[static_cast<size_t>(i)] > known) top = std::min(top, roots[static_cast<size_t>(i)]);
    }
  };
  for (int i = begin; i < end; ++i) {
    const LinearRow& row = problem.rows[static_cast<size_t>(i)];
    if (row.at != 0.0) continue;
    if (row.alpha == 0.0) {
      limit({row.beta, row.gamma, 0.0, row.lo, row.hi});
      continue;
    }
    const double low = row.alpha > 0.0 ? row.lo : row.hi, high = row.alpha > 0.0 ? row.hi : row.lo;
    const double c2 = -row.beta / row.alpha, c1 = -row.gamma / row.alpha;
    if (std::isfinite(low) && lowers < kMaxCandidates) lower[static_cast<size_t>(lowers++)] = {c2, c1, low / row.alpha};
    if (std::isfinite(high) && uppers < kMaxCandidates)
      upper[static_cast<size_t>(uppers++)] = {c2, c1, high / row.alpha};
  }
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (int i = 0; i < lowers; ++i) {
    const Bound& l = lower[static_cast<size_t>(i)];
    // c^2 + 2 a ds <= next at the lowest a: l(c) - (next - c^2) / (2 ds) <= 0.
    limit({l.c2 + inv, l.c1, l.c0 - next * inv, -kInf, 0.0});
    for (int j = 0; j < uppers; ++j) {
      const Bound& u = upper[static_cast<size_t>(j)];
      limit({l.c2 - u.c2, l.c1 - u.c1, l.c0 - u.c0, -kInf, 0.0});
    }
  }
  return feasible ? top : known;
}

}  // namespace

AccelInterval admissibleAcceleration(const Problem& problem, int interval, double b) {
  const double c = std::sqrt(std::max(0.0, b));
  AccelInterval out{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  const int begin = problem.row_begin[static_cast<size_t>(interval)];
  const int end = problem.row_begin[static_cast<size_t>(interval) + 1];
  for (int i = begin; i < end; ++i) {
    const LinearRow& row = problem.rows[static_cast<size_t>(i)];
    if (row.at != 0.0) continue;
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
  IntervalForms forms;
  const int rows = intervalForms(problem, interval, forms);
  return largestFreeSpeed(forms, rows, c_now, true, c_next_max);
}

ReachabilityResult forwardBackward(const Problem& problem, std::vector<double>& b, std::vector<double>& controllable,
                                   double start_speed_tolerance) {
  ReachabilityResult result;
  const int k_points = problem.gridPoints();
  b.assign(static_cast<size_t>(k_points), 0.0);
  controllable.assign(static_cast<size_t>(k_points), 0.0);
  const int last = k_points - 1;

  controllable[static_cast<size_t>(last)] = problem.b_end;
  double previous = 0.0;  // C of the node after: the starting guess for this one
  for (int k = last - 1; k >= 0; --k) {
    const double c_next = std::sqrt(controllable[static_cast<size_t>(k) + 1]);
    // Usually the largest c_k is the one that lands exactly on sqrt(C_{k+1}) (braking binds);
    // where c_k is limited by its own limits a harder braking may allow more, so search above.
    IntervalForms forms;
    const int rows = intervalForms(problem, k, forms);
    auto stoppable = [&](double c) { return reachable(forms, rows, c, c_next); };
    double c = largestFreeSpeed(forms, rows, c_next, false, problem.speed_bound);
    if (c < 0.0) {
      if (!stoppable(0.0)) {
        result.status = ReachabilityStatus::kNotControllable;
        result.reason =
            fmt::format("the path cannot be followed even slowly near s = {:.4f}", problem.s[static_cast<size_t>(k)]);
        return result;
      }
      c = 0.0;
    }
    if (stoppable(c * (1.0 + kRelativeRoundoff) + kAbsoluteRoundoff)) {
      // The left-end rows alone (a linear interval in a) bound c_k cheaply from above; all rows
      // are checked there and searched below it only when the right-end rows cut it down.
      const double guess = std::max(c, previous);
      const double c_left = leftStoppableAbove(problem, k, c_next * c_next, c, problem.speed_bound);
      c = stoppable(c_left)
              ? c_left
              : largestTrueNear(stoppable, c, std::min(guess, c_left), c_left, problem.controllable_tolerance);
    }
    previous = c;
    controllable[static_cast<size_t>(k)] = c * c;
  }
  result.controllable_start_b = controllable[0];

  const double slack = 1.0 + std::max(0.0, start_speed_tolerance);
  const bool beyond = problem.b_start > controllable[0] * (1.0 + kRelativeRoundoff) + kAbsoluteRoundoff;
  if (beyond && problem.b_start > controllable[0] * slack * slack * (1.0 + kRelativeRoundoff) + kAbsoluteRoundoff) {
    result.status = ReachabilityStatus::kStartNotControllable;
    result.reason = fmt::format(
        "start speed^2 b = {:.6g} along the path cannot be brought to rest within the limits "
        "(largest controllable b = {:.6g})",
        problem.b_start, controllable[0]);
    return result;
  }
  result.start_b = beyond ? controllable[0] : problem.b_start;
  b[0] = result.start_b;
  double c = std::sqrt(result.start_b);
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

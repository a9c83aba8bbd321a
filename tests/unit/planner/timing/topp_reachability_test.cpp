// The forward-backward pass (topp_reachability.hpp) against every row it must respect: the
// profile within its rows and its controllable set, each controllable speed the top of the
// stoppable ones, the largest next speed and the admissible accelerations against dense scans,
// and the starts it refuses or clamps.

#include "timing/topp_reachability.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "topp_fixtures.hpp"

namespace cyber::planner {
namespace {

// Whether every row of interval k holds within `tolerance` at (a, b0, b1, c0, c1); only those at
// its left node when `left_node_only`.
bool rowsHold(const topp::Problem& p, int k, double a, double b0, double b1, double c0, double c1, double tolerance,
              bool left_node_only = false) {
  for (int i = p.row_begin[static_cast<size_t>(k)]; i < p.row_begin[static_cast<size_t>(k) + 1]; ++i) {
    const topp::LinearRow& row = p.rows[static_cast<size_t>(i)];
    if (left_node_only && row.at != 0.0) continue;
    const double v = row.value(a, b0, b1, c0, c1);
    if (v > row.hi + tolerance || v < row.lo - tolerance) return false;
  }
  return true;
}

// The S-curve's problem with its controllable set (the backward pass's C_k at each node).
struct Controllable {
  topp::Problem p;
  std::vector<double> c;
};

Controllable controllableSet(double b_start = 0.0) {
  Controllable out{testing::wiggleProblem(150, b_start), {}};
  std::vector<double> b;
  EXPECT_EQ(topp::forwardBackward(out.p, b, out.c).status, topp::ReachabilityStatus::kOk);
  return out;
}

TEST(ToppReachability, ProfileSatisfiesEveryRowAndIsControllable) {
  const topp::Problem p = testing::wiggleProblem(150);
  std::vector<double> b, controllable;
  const topp::ReachabilityResult r = topp::forwardBackward(p, b, controllable);
  ASSERT_EQ(r.status, topp::ReachabilityStatus::kOk) << r.reason;
  EXPECT_EQ(b.front(), 0.0);
  EXPECT_EQ(b.back(), 0.0);
  for (int k = 0; k < p.intervals(); ++k) {
    EXPECT_LE(b[static_cast<size_t>(k)], controllable[static_cast<size_t>(k)] * (1 + 1e-9) + 1e-12);
    const double a = (b[static_cast<size_t>(k) + 1] - b[static_cast<size_t>(k)]) / (2.0 * p.ds(k));
    const double c0 = std::sqrt(b[static_cast<size_t>(k)]), c1 = std::sqrt(b[static_cast<size_t>(k) + 1]);
    for (int i = p.row_begin[static_cast<size_t>(k)]; i < p.row_begin[static_cast<size_t>(k) + 1]; ++i) {
      const topp::LinearRow& row = p.rows[static_cast<size_t>(i)];
      const double v = row.value(a, b[static_cast<size_t>(k)], b[static_cast<size_t>(k) + 1], c0, c1);
      EXPECT_LE(v, row.hi + 1e-7) << "interval " << k << " at " << row.at;
      EXPECT_GE(v, row.lo - 1e-7) << "interval " << k << " at " << row.at;
    }
  }
  // A start faster than C_0 is reported as such.
  topp::Problem fast = testing::wiggleProblem(150, 1.5 * r.controllable_start_b);
  EXPECT_EQ(topp::forwardBackward(fast, b, controllable).status, topp::ReachabilityStatus::kStartNotControllable);
  EXPECT_EQ(topp::forwardBackward(fast, b, controllable, 0.2).status, topp::ReachabilityStatus::kStartNotControllable);
  // Within the start tolerance it starts from C_0 (the edge of the controllable set) instead.
  // (C_0 of a moving start: a start at rest pins the first node to qdot = 0, which changes its rows.)
  const double edge = topp::forwardBackward(testing::wiggleProblem(150, 0.5 * r.controllable_start_b), b, controllable)
                          .controllable_start_b;
  topp::Problem near_edge = testing::wiggleProblem(150, 1.01 * 1.01 * edge);
  EXPECT_EQ(topp::forwardBackward(near_edge, b, controllable, 0.005).status,
            topp::ReachabilityStatus::kStartNotControllable);
  const topp::ReachabilityResult clamped = topp::forwardBackward(near_edge, b, controllable, 0.02);
  ASSERT_EQ(clamped.status, topp::ReachabilityStatus::kOk);
  EXPECT_EQ(clamped.start_b, clamped.controllable_start_b);
  EXPECT_EQ(b.front(), clamped.controllable_start_b);
}

// Each node's controllable speed is the top of the speeds from which the node after can be reached
// within its own controllable speed: every speed up to it can (scanned), and a speed 10^-4 above
// it cannot (fastestNextSpeed, checked against a scan below, answers "can").
TEST(ToppReachability, ControllableSpeedIsTheTopOfTheStoppableSpeedsAtEveryNode) {
  for (const double b_start : {0.0, 0.5}) {
    const auto [p, controllable] = controllableSet(b_start);
    int capped = 0;
    for (int k = 0; k < p.intervals(); ++k) {
      const double c_top = std::sqrt(controllable[static_cast<size_t>(k)]);
      const double c_next = std::sqrt(controllable[static_cast<size_t>(k) + 1]);
      auto stoppable = [&](double c) { return topp::fastestNextSpeed(p, k, c, c_next) >= 0.0; };
      for (int i = 0; i <= 50; ++i) EXPECT_TRUE(stoppable(c_top * i / 50)) << "node " << k << ", " << i << "/50";
      if (c_top < 0.99 * p.speed_bound) {
        ++capped;
        EXPECT_FALSE(stoppable(c_top * (1.0 + 1e-4) + 1e-9)) << "node " << k << ": C_k could be larger";
      }
    }
    EXPECT_GT(capped, 100);
  }
}

// The largest next speed against a dense scan of [0, c_max] (the rows' feasible set can be a
// union of intervals, so the scan looks at all of it): the answer satisfies every row, and no
// scanned speed above it does.
TEST(ToppReachability, FastestNextSpeedIsTheLargestFeasibleOverSeededStates) {
  const auto [p, controllable] = controllableSet();
  auto within = [&](int k, double c0, double c1, double tolerance) {
    const double b0 = c0 * c0, b1 = c1 * c1;
    return rowsHold(p, k, (b1 - b0) / (2.0 * p.ds(k)), b0, b1, c0, c1, tolerance);
  };
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> interval(0, p.intervals() - 1);
  std::uniform_real_distribution<double> fraction(0.0, 1.3);
  int found = 0, none = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int k = interval(rng);
    const double c_cap = std::sqrt(std::max(controllable[static_cast<size_t>(k)], 1e-6));
    const double c_now = fraction(rng) * c_cap;
    const double c_max = fraction(rng) * std::sqrt(std::max(controllable[static_cast<size_t>(k) + 1], 1e-6));
    const double c_next = topp::fastestNextSpeed(p, k, c_now, c_max);
    constexpr int kScan = 4000;
    double scanned = -1.0;
    for (int i = kScan; i >= 0; --i) {
      const double c = c_max * i / kScan;
      if (within(k, c_now, c, 0.0)) {
        scanned = c;
        break;
      }
    }
    if (c_next < 0.0) {
      ++none;
      EXPECT_LT(scanned, 0.0) << "trial " << trial << ": none found, but " << scanned << " is feasible";
      continue;
    }
    ++found;
    EXPECT_LE(c_next, c_max) << "trial " << trial;
    EXPECT_TRUE(within(k, c_now, c_next, 1e-9)) << "trial " << trial << " c_next " << c_next;
    EXPECT_LE(scanned, c_next * (1.0 + 1e-9) + 1e-12) << "trial " << trial << ": " << scanned << " above " << c_next;
  }
  EXPECT_GT(found, 200);
  EXPECT_GT(none, 10);
}

// The accelerations the rows at an interval's left node admit, against a scan of them: every
// scanned a inside [lo, hi] satisfies each of those rows, none outside does, and the ends are on a
// row's bound.
TEST(ToppReachability, AdmissibleAccelerationIsWhatTheLeftNodesRowsAllow) {
  const auto [p, controllable] = controllableSet();
  auto holds = [&](int k, double node_b, double a, double tolerance) {
    const double c = std::sqrt(node_b);
    return rowsHold(p, k, a, node_b, node_b, c, c, tolerance, true);
  };
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> interval(0, p.intervals() - 1);
  std::uniform_real_distribution<double> fraction(0.0, 1.5);
  int bounded = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int k = interval(rng);
    const double node_b = fraction(rng) * std::max(controllable[static_cast<size_t>(k)], 1e-6);
    const topp::AccelInterval range = topp::admissibleAcceleration(p, k, node_b);
    if (range.empty()) {
      for (double a = -1e3; a <= 1e3; a += 1.0) ASSERT_FALSE(holds(k, node_b, a, 0.0)) << "trial " << trial;
      continue;
    }
    ++bounded;
    ASSERT_TRUE(std::isfinite(range.lo) && std::isfinite(range.hi)) << "trial " << trial;
    EXPECT_TRUE(holds(k, node_b, range.lo, 1e-9)) << "trial " << trial;
    EXPECT_TRUE(holds(k, node_b, range.hi, 1e-9)) << "trial " << trial;
    const double width = std::max(range.hi - range.lo, 1e-6);
    EXPECT_FALSE(holds(k, node_b, range.lo - 1e-6 * width, 0.0)) << "trial " << trial;
    EXPECT_FALSE(holds(k, node_b, range.hi + 1e-6 * width, 0.0)) << "trial " << trial;
    for (int i = 1; i < 100; ++i) {
      EXPECT_TRUE(holds(k, node_b, range.lo + (range.hi - range.lo) * i / 100, 1e-9)) << "trial " << trial;
    }
  }
  EXPECT_GT(bounded, 100);
}

}  // namespace
}  // namespace cyber::planner

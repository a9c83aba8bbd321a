// The continuous clearance checks (path_clearance.hpp) against brute force: the reef scene's
// signed distance sampled densely along seeded segments and splines. A segment or path judged
// clear dips below the clearance by no more than half a dense step can hide (between two samples
// at or above it); one judged not clear has a pose closer than the clearance where the check
// says, and nothing deeper than a dense step can hide before it; certified steps spend fewer
// evaluations than dense sampling where the margin allows; the spline's joint range is exact.

#include "path/path_clearance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "reference_model.hpp"

namespace cyber::planner {
namespace {

// Brute force: the smallest distance over samples no more than kBruteStep apart in any joint.
constexpr double kBruteStep = 2.5e-4;

struct Scan {
  double min_distance = std::numeric_limits<double>::infinity();
  double first_deep = -1.0;  // the first parameter below `deep`, or -1
};

template <class Curve>
Scan scan(const CollisionWorld& world, Curve&& q_at, double u0, double u1, double speed, double deep) {
  Scan out;
  const int steps = std::max(1, static_cast<int>(std::ceil((u1 - u0) * speed / kBruteStep)));
  for (int i = 0; i <= steps; ++i) {
    const double u = u0 + (u1 - u0) * i / steps;
    const double d = world.distance(q_at(u)).value;
    out.min_distance = std::min(out.min_distance, d);
    if (d < deep && out.first_deep < 0.0) out.first_deep = u;
  }
  return out;
}

// A check's verdict against the dense scan of the same curve (distance_at: the exact distance at a
// parameter of it). Clear: no sample of the scan is below the clearance by more than half a dense
// step can hide, and the smallest distance the check saw keeps the clearance. Not clear: the check
// stopped at a pose closer than the clearance, exact there, and nothing deeper than a dense step
// can hide comes before it.
struct Verdicts {
  int clear = 0;
  int refused = 0;
};

template <class DistanceAt>
void expectTheScansVerdict(const ClearanceCheck& check, const Scan& dense, double clearance, double step_hides,
                           DistanceAt&& distance_at, int trial, Verdicts& verdicts) {
  if (check.clear) {
    ++verdicts.clear;
    EXPECT_GE(dense.min_distance, clearance - 0.5 * step_hides) << "trial " << trial;
    EXPECT_GE(check.min_distance_m, clearance) << "trial " << trial;
    return;
  }
  ++verdicts.refused;
  EXPECT_LT(check.min_distance_m, clearance) << "trial " << trial;
  EXPECT_NEAR(distance_at(check.at_s), check.min_distance_m, 1e-12) << "trial " << trial;
  if (dense.first_deep >= 0.0) {
    EXPECT_GE(dense.first_deep, check.at_s - 1e-12) << "trial " << trial;
  }
}

JointVector randomPose(const RobotModel& model, std::mt19937& rng) {
  std::uniform_real_distribution<double> e(model.range(0).min, model.range(0).max);
  std::uniform_real_distribution<double> a(model.range(1).min, model.range(1).max);
  const double elevator = e(rng);
  return JointVector{{elevator, a(rng)}};
}

// A seeded segment from a pose anywhere in the range: up to 25 cm and 0.8 rad long.
struct Segment {
  JointVector from;
  JointVector delta;
};

Segment randomSegment(const RobotModel& model, std::mt19937& rng) {
  std::uniform_real_distribution<double> de(-0.25, 0.25), da(-0.8, 0.8);
  const JointVector from = randomPose(model, rng);
  const double elevator = de(rng);
  return {from, JointVector{{elevator, da(rng)}}};
}

struct Reef {
  const RobotModel& model = test::referenceModel();
  CollisionWorld world{model, model.scenes.front(), HeldPieces{}};
};

// A world without obstacles: only the joint range can refuse a path there.
CollisionWorld emptyWorld(const RobotModel& model) {
  Scene empty = model.scenes.front();
  empty.obstacles.clear();
  empty.fixed.clear();
  return CollisionWorld(model, empty, HeldPieces{});
}

TEST(PathClearance, SegmentsAgreeWithDenseSampling) {
  const Reef reef;
  const double clearance = reef.model.clearance_m;
  std::mt19937 rng(41);
  Verdicts verdicts;
  for (int trial = 0; trial < 80; ++trial) {
    const auto [a, delta] = randomSegment(reef.model, rng);
    const JointVector b = a + delta;
    const ClearanceCheck check = checkSegment(reef.world, a, b, clearance);
    // What a dense step (kDenseCheckStep in the fastest joint) can hide next to a sample: the
    // distance changes by at most the Lipschitz bound times the step.
    const double step_hides =
        reef.world.lipschitzBound(delta.cwiseAbs()) * kDenseCheckStep / delta.cwiseAbs().maxCoeff();
    const Scan dense = scan(
        reef.world, [&](double u) { return JointVector(a + u * delta); }, 0.0, 1.0, delta.cwiseAbs().maxCoeff(),
        clearance - step_hides);
    EXPECT_GT(check.evaluations, 0);
    expectTheScansVerdict(
        check, dense, clearance, step_hides, [&](double u) { return reef.world.distance(a + u * delta).value; }, trial,
        verdicts);
  }
  EXPECT_GT(verdicts.clear, 10);
  EXPECT_GT(verdicts.refused, 10);
}

// Segments with room to spare (5 cm more than the clearance all the way, by dense sampling) take
// certified steps: a quarter of the dense samples at most. A coarser dense step never takes more.
TEST(PathClearance, CertifiedStepsSpendFewerEvaluationsThanDenseSamplingWithRoom) {
  const Reef reef;
  const double clearance = reef.model.clearance_m;
  std::mt19937 rng(47);
  int roomy = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const auto [a, delta] = randomSegment(reef.model, rng);
    const Scan dense = scan(
        reef.world, [&](double u) { return JointVector(a + u * delta); }, 0.0, 1.0, delta.cwiseAbs().maxCoeff(), 0.0);
    if (dense.min_distance < clearance + 0.05) continue;
    ++roomy;
    const ClearanceCheck check = checkSegment(reef.world, a, a + delta, clearance);
    EXPECT_TRUE(check.clear) << "trial " << trial;
    EXPECT_LT(check.evaluations, 0.25 * delta.cwiseAbs().maxCoeff() / kDenseCheckStep) << "trial " << trial;
    EXPECT_LE(checkSegment(reef.world, a, a + delta, clearance, 10 * kDenseCheckStep).evaluations, check.evaluations)
        << "trial " << trial;
  }
  EXPECT_GE(roomy, 5);
  // With no obstacle at all, one evaluation at each end.
  const ClearanceCheck free =
      checkSegment(emptyWorld(reef.model), JointVector{{0.1, 1.4}}, JointVector{{0.4, 2.2}}, clearance);
  EXPECT_TRUE(free.clear);
  EXPECT_EQ(free.evaluations, 2);
}

// Steps between known ends (checkStep, the C-space grid's steps): judged as their dense samples
// are, with the ends' distances exact or only lower bounds.
TEST(PathClearance, StepsBetweenKnownEndsAgreeWithDenseSampling) {
  const Reef reef;
  const double clearance = reef.model.clearance_m;
  std::mt19937 rng(53);
  std::uniform_real_distribution<double> shrink(0.05, 1.0);
  int clear = 0, refused = 0, lower_bounds = 0;
  for (int trial = 0; trial < 600; ++trial) {
    // Every third step is centred on a pose closer than the clearance, so that some cross an obstacle.
    auto [a, delta] = randomSegment(reef.model, rng);
    delta *= shrink(rng);  // from a grid step's length to a long segment
    if (trial % 3 == 0) {
      JointVector middle = randomPose(reef.model, rng);
      while (!(reef.world.distance(middle).value < clearance)) middle = randomPose(reef.model, rng);
      // Widened until both ends are free, if they ever are within the joint range.
      for (double half = 0.05; half < 2.0; half *= 1.25) {
        a = middle - half * delta;
        if (reef.model.withinLimits(a) && reef.model.withinLimits(a + 2.0 * half * delta) &&
            reef.world.distance(a).value >= clearance &&
            reef.world.distance(a + 2.0 * half * delta).value >= clearance) {
          delta *= 2.0 * half;
          break;
        }
      }
    }
    const JointVector b = a + delta;
    const double d_a = reef.world.distance(a).value, d_b = reef.world.distance(b).value;
    if (d_a < clearance || d_b < clearance) continue;  // steps join free nodes only
    // Half the time an end is known only as a lower bound (a cutoff just above the clearance).
    const double cutoff = clearance + 0.01;
    const bool bounded = trial % 2 == 1;
    const double known_a = bounded ? reef.world.distance(a, cutoff).value : d_a;
    const double known_b = bounded ? reef.world.distance(b, cutoff).value : d_b;
    lower_bounds += known_a != d_a || known_b != d_b ? 1 : 0;
    const StepCheck step = checkStep(reef.world, a, b, clearance, known_a, known_b);
    const double step_hides =
        reef.world.lipschitzBound(delta.cwiseAbs()) * kDenseCheckStep / delta.cwiseAbs().maxCoeff();
    const Scan dense = scan(
        reef.world, [&](double u) { return JointVector(a + u * delta); }, 0.0, 1.0, delta.cwiseAbs().maxCoeff(),
        clearance);
    if (step.clear) {
      ++clear;
      EXPECT_GE(dense.min_distance, clearance - 0.5 * step_hides) << "trial " << trial;
    } else {
      ++refused;
      EXPECT_LT(dense.min_distance, clearance) << "trial " << trial;
      EXPECT_GT(step.evaluations, 0) << "trial " << trial;
    }
    // A whole step its ends' cones clear costs no distance at all.
    if (0.5 * (known_a + known_b - reef.world.lipschitzBound(delta.cwiseAbs())) >= clearance) {
      EXPECT_EQ(step.evaluations, 0) << "trial " << trial;
    }
  }
  EXPECT_GT(clear, 50);
  EXPECT_GT(refused, 10);
  EXPECT_GT(lower_bounds, 20);
}

// Seeded splines through nearby waypoints: judged as their dense samples are, and on success the
// reported minimum is an exact distance on the path no further than a dense step from the
// sampled one.
TEST(PathClearance, SplinesAgreeWithDenseSampling) {
  const Reef reef;
  const double clearance = reef.model.clearance_m;
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> de(-0.12, 0.12), da(-0.4, 0.4);
  Verdicts verdicts;
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<JointVector> waypoints{randomPose(reef.model, rng)};
    for (int k = 0; k < 3; ++k) {
      const double step_e = de(rng);
      const JointVector next = waypoints.back() + JointVector{{step_e, da(rng)}};
      waypoints.push_back(next.cwiseMax(JointVector{{reef.model.range(0).min, reef.model.range(1).min}})
                              .cwiseMin(JointVector{{reef.model.range(0).max, reef.model.range(1).max}}));
    }
    const auto path = CubicSplinePath::through(waypoints, reef.model.planner.metric);
    ASSERT_TRUE(path.ok());
    const CubicSplinePath& p = path.value();
    const ClearanceCheck check = checkPath(p, reef.world, reef.model, clearance);
    if (!check.within_limits) continue;  // an overshoot past a limit: SplineLeavingTheRange
    double speed = 0.0, lipschitz = 0.0, step_hides = 0.0;
    for (int k = 0; k < p.segmentCount(); ++k) {
      const JointVector bound = p.segmentBounds(k).abs_dq_max;
      speed = std::max(speed, bound.maxCoeff());
      lipschitz = std::max(lipschitz, reef.world.lipschitzBound(bound));
      step_hides = std::max(step_hides, reef.world.lipschitzBound(bound) * kDenseCheckStep / bound.maxCoeff());
    }
    const Scan dense = scan(
        reef.world, [&](double s) { return p.at(s).q; }, 0.0, p.length(), speed, clearance - step_hides);
    expectTheScansVerdict(
        check, dense, clearance, step_hides, [&](double u) { return reef.world.distance(p.at(u).q).value; }, trial,
        verdicts);
    // On success the reported minimum is refined by a dense scan near it: no further below the
    // sampled one than the scan's own spacing can hide.
    if (check.clear) {
      EXPECT_EQ(reef.world.distance(p.at(check.at_s).q).value, check.min_distance_m) << "trial " << trial;
      EXPECT_GE(check.min_distance_m, dense.min_distance - 0.5 * lipschitz * kBruteStep / speed) << "trial " << trial;
    }
  }
  EXPECT_GT(verdicts.clear, 5);
  EXPECT_GT(verdicts.refused, 5);
}

// The joint range is judged on each segment's exact bounds: a spline that overshoots a limit
// between waypoints inside the range is refused at the start of that segment.
TEST(PathClearance, SplineLeavingTheRangeIsRefusedAtItsSegment) {
  const Reef reef;
  const CollisionWorld nothing = emptyWorld(reef.model);
  const double top = reef.model.range(0).max;
  // A fast rise that turns just below the top of the elevator: the natural spline overshoots it
  // (by about 2 cm).
  const std::vector<JointVector> waypoints{JointVector{{1.0, 3.0}}, JointVector{{1.9, 3.02}},
                                           JointVector{{top - 1e-3, 3.04}}, JointVector{{1.5, 3.06}}};
  const auto path = CubicSplinePath::through(waypoints, reef.model.planner.metric);
  ASSERT_TRUE(path.ok());
  double highest = 0.0;
  for (int i = 0; i <= 10000; ++i)
    highest = std::max(highest, path.value().at(path.value().length() * i / 10000).q.x());
  ASSERT_GT(highest, top) << "the spline was meant to overshoot";
  const ClearanceCheck check = checkPath(path.value(), nothing, reef.model, reef.model.clearance_m);
  EXPECT_FALSE(check.within_limits);
  EXPECT_FALSE(check.ok());
  int segment = 0;
  while (path.value().segmentBounds(segment).q_max.x() <= top) ++segment;
  EXPECT_EQ(check.at_s, path.value().knots()[static_cast<size_t>(segment)]);
  // The same turn further down stays inside.
  std::vector<JointVector> lower = waypoints;
  for (JointVector& w : lower) w.x() -= 0.5;
  const auto inside = CubicSplinePath::through(lower, reef.model.planner.metric);
  ASSERT_TRUE(inside.ok());
  EXPECT_TRUE(checkPath(inside.value(), nothing, reef.model, reef.model.clearance_m).ok());
}

// A single pose: its own distance and range decide.
TEST(PathClearance, AZeroLengthPathIsThePoseItself) {
  const Reef reef;
  const JointVector pose{{0.3, 1.8}};
  const JointVector both[] = {pose, pose};
  const auto path = CubicSplinePath::through(both, reef.model.planner.metric);
  ASSERT_TRUE(path.ok());
  ASSERT_EQ(path.value().segmentCount(), 0);
  const double d = reef.world.distance(pose).value;
  const ClearanceCheck check = checkPath(path.value(), reef.world, reef.model, reef.model.clearance_m);
  EXPECT_EQ(check.clear, d >= reef.model.clearance_m);
  EXPECT_TRUE(check.within_limits);
  const ClearanceCheck too_close = checkPath(path.value(), reef.world, reef.model, d + 1e-6);
  EXPECT_FALSE(too_close.clear);
  EXPECT_EQ(too_close.min_distance_m, d);
  EXPECT_TRUE(checkPath(path.value(), reef.world, reef.model, d - 1e-6).clear);
  // Outside the range, the pose is refused whatever its distance.
  const JointVector above[] = {JointVector{{reef.model.range(0).max + 0.01, 1.8}}};
  const auto out = CubicSplinePath::through(above, reef.model.planner.metric);
  ASSERT_TRUE(out.ok());
  EXPECT_FALSE(checkPath(out.value(), reef.world, reef.model, 0.0).within_limits);
}

}  // namespace
}  // namespace cyber::planner

#include "cyber/daemon/program.hpp"

#include <gtest/gtest.h>

#include "fake_trajectory.hpp"
#include "reference_model.hpp"
#include "splice_into.hpp"

namespace cyber::daemon {
namespace {

using test::makeHermite;
constexpr MonoNs kMs = 1'000'000;

class ProgramTest : public ::testing::Test {
 protected:
  const planner::RobotModel& robot = cyber::test::referenceModel();
  HoldModel hold{robot};

  Segment segment(std::int64_t id, JointVector from, JointVector velocity, JointVector to, double duration_s,
                  MonoNs start) const {
    return Segment{makeHermite(from, velocity, to, duration_s, robot), id, start};
  }
};

TEST_F(ProgramTest, WithoutSegmentsItHoldsWithGravityFeedforward) {
  const JointVector q{{0.8, 0.6}};
  const Program program = Program::holdAt(3, q);
  const ProgramSample s = program.sample(123 * kMs, hold);
  EXPECT_EQ(s.request_id, -1);
  EXPECT_FALSE(s.moving);
  EXPECT_EQ(s.setpoints.position, q);
  EXPECT_EQ(s.setpoints.velocity, JointVector::Zero(2));
  EXPECT_DOUBLE_EQ(s.setpoints.volts[0], robot.drive(0).kG_volts);
  EXPECT_DOUBLE_EQ(s.setpoints.volts[1], robot.drive(1).kG_volts * std::cos(0.6));
  EXPECT_EQ(program.endNs(), kNever);
  EXPECT_EQ(program.restPosition(), q);
}

TEST_F(ProgramTest, FloatingSpliceStartsFromRestAtAdoption) {
  const JointVector q0{{0.2, 1.0}}, q1{{1.0, 2.0}};
  const Program base = Program::holdAt(1, q0);
  Program next;
  std::vector<std::int64_t> dropped;
  ASSERT_TRUE(
      test::spliceInto(base, {0, segment(5, q0, JointVector::Zero(2), q1, 0.5, kNever), true, 9}, next, dropped));
  EXPECT_TRUE(dropped.empty());
  EXPECT_EQ(next.id, 9u);
  EXPECT_EQ(next.base_id, 0u);
  EXPECT_EQ(next.epoch, 1u);
  next.resolveFloatingStart(40 * kMs);
  EXPECT_EQ(next.segment(0).start_ns, 40 * kMs);
  EXPECT_EQ(next.endNs(), 540 * kMs);
  // Before the start it still holds the rest position; at the end it holds q1.
  EXPECT_EQ(next.sample(39 * kMs, hold).setpoints.position, q0);
  const ProgramSample mid = next.sample(290 * kMs, hold);
  EXPECT_TRUE(mid.moving);
  EXPECT_EQ(mid.request_id, 5);
  EXPECT_TRUE(mid.last_segment);
  const ProgramSample end = next.sample(600 * kMs, hold);
  EXPECT_FALSE(end.moving);
  EXPECT_EQ(end.request_id, 5);
  EXPECT_TRUE(end.setpoints.position.isApprox(q1));
  EXPECT_EQ(end.setpoints.velocity, JointVector::Zero(2));
  EXPECT_EQ(next.restPosition(), end.setpoints.position);
}

TEST_F(ProgramTest, FloatingStartWaitsForTheRunningMotionToEnd) {
  const JointVector q0{{0.2, 1.0}}, q1{{1.0, 2.0}}, q2{{0.5, 0.5}};
  Program base = Program::holdAt(1, q0);
  std::vector<std::int64_t> dropped;
  Program one;
  ASSERT_TRUE(
      test::spliceInto(base, {0, segment(1, q0, JointVector::Zero(2), q1, 0.5, kNever), true, 1}, one, dropped));
  one.resolveFloatingStart(0);
  Program two;
  ASSERT_TRUE(
      test::spliceInto(one, {100 * kMs, segment(2, q1, JointVector::Zero(2), q2, 0.5, kNever), true, 2}, two, dropped));
  two.resolveFloatingStart(100 * kMs);
  ASSERT_EQ(two.segmentCount(), 2);
  EXPECT_EQ(two.segment(1).start_ns, 500 * kMs);
}

TEST_F(ProgramTest, FixedSpliceEqualsTheBaseBeforeItAndContinuesPositionAndVelocity) {
  const JointVector q0{{0.2, 1.0}}, q1{{1.5, 3.0}}, q2{{0.4, 0.3}};
  Program base;
  std::vector<std::int64_t> dropped;
  ASSERT_TRUE(test::spliceInto(Program::holdAt(1, q0),
                               {0, segment(1, q0, JointVector::Zero(2), q1, 1.0, kNever), true, 1}, base, dropped));
  base.resolveFloatingStart(0);
  const MonoNs t_b = 400 * kMs;
  const ProgramSample at_branch = base.sample(t_b, hold);
  ASSERT_TRUE(at_branch.moving);
  Program next;
  ASSERT_TRUE(test::spliceInto(
      base, {370 * kMs, segment(2, at_branch.setpoints.position, at_branch.setpoints.velocity, q2, 0.8, t_b), false, 2},
      next, dropped));
  EXPECT_EQ(next.splice_ns, t_b);
  for (MonoNs t = 370 * kMs; t < t_b; t += kMs) {
    EXPECT_EQ(next.sample(t, hold).setpoints.position, base.sample(t, hold).setpoints.position) << t;
  }
  // Left and right limits at the splice agree in position and velocity.
  const ProgramSample left = base.sample(t_b, hold);
  const ProgramSample right = next.sample(t_b, hold);
  EXPECT_EQ(right.request_id, 2);
  EXPECT_LT((left.setpoints.position - right.setpoints.position).norm(), 1e-12);
  EXPECT_LT((left.setpoints.velocity - right.setpoints.velocity).norm(), 1e-12);
}

TEST_F(ProgramTest, SpliceDropsSegmentsThatWouldStartAfterItAndPrunesFinishedOnes) {
  const JointVector a{{0.2, 1.0}}, b{{1.0, 1.5}}, c{{1.2, 2.0}}, d{{0.3, 0.2}};
  Program p;
  std::vector<std::int64_t> dropped;
  ASSERT_TRUE(test::spliceInto(Program::holdAt(1, a), {0, segment(1, a, JointVector::Zero(2), b, 1.0, kNever), true, 1},
                               p, dropped));
  p.resolveFloatingStart(0);
  Program q;
  ASSERT_TRUE(
      test::spliceInto(p, {10 * kMs, segment(2, b, JointVector::Zero(2), c, 1.0, 500 * kMs), false, 2}, q, dropped));
  ASSERT_EQ(q.segmentCount(), 2);
  // A plan branching at 300 ms replaces request 2, which never started.
  Program r;
  ASSERT_TRUE(
      test::spliceInto(q, {20 * kMs, segment(3, c, JointVector::Zero(2), d, 1.0, 300 * kMs), false, 3}, r, dropped));
  ASSERT_EQ(dropped, std::vector<std::int64_t>{2});
  ASSERT_EQ(r.segmentCount(), 2);
  EXPECT_EQ(r.segment(0).request_id, 1);
  EXPECT_EQ(r.segment(1).request_id, 3);
  // At 600 ms segment 1 can no longer be sampled: it is pruned and the rest position follows it.
  Program s;
  dropped.clear();
  ASSERT_TRUE(
      test::spliceInto(r, {600 * kMs, segment(4, d, JointVector::Zero(2), a, 1.0, 900 * kMs), false, 4}, s, dropped));
  EXPECT_TRUE(dropped.empty());
  ASSERT_EQ(s.segmentCount(), 2);
  EXPECT_EQ(s.segment(0).request_id, 3);
  EXPECT_EQ(s.segment(1).request_id, 4);
  EXPECT_TRUE(s.rest_q.isApprox(b));
  // The pruned segment is reported with the one that superseded it (no streamer event may name it).
  const auto spliced =
      Program::splice(r, {600 * kMs, segment(4, d, JointVector::Zero(2), a, 1.0, 900 * kMs), false, 4});
  ASSERT_TRUE(spliced);
  EXPECT_EQ(spliced->pruned_requests, (std::vector<std::pair<std::int64_t, std::int64_t>>{{1, 3}}));
  EXPECT_TRUE(Program::splice(r, {20 * kMs, segment(4, d, JointVector::Zero(2), a, 1.0, 900 * kMs), false, 4})
                  ->pruned_requests.empty());
}

TEST_F(ProgramTest, AFullChainRefusesAnotherSegmentAndReportsNothingDropped) {
  const JointVector a{{0.2, 1.0}};
  Program p = Program::holdAt(1, a);
  std::vector<std::int64_t> dropped;
  for (int i = 0; i < kMaxSegments; ++i) {
    Program next;
    ASSERT_TRUE(test::spliceInto(p,
                                 {0, segment(i, a, JointVector::Zero(2), a, 10.0, (i + 1) * 100 * kMs), false,
                                  static_cast<std::uint64_t>(i + 1)},
                                 next, dropped));
    p = next;
  }
  EXPECT_TRUE(p.full());
  Program refused;
  dropped = {42};
  EXPECT_FALSE(
      test::spliceInto(p, {0, segment(99, a, JointVector::Zero(2), a, 1.0, 5000 * kMs), false, 99}, refused, dropped));
  EXPECT_EQ(dropped, std::vector<std::int64_t>{42});
}

}  // namespace
}  // namespace cyber::daemon

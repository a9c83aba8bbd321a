// The pieces of a "stop first" plan (joined_path.hpp, docs/moving-starts.md): the straight piece
// in closed form, the joined path continuous at its junction with the second piece answering
// there, and two trajectories joined at rest into one that replays each in turn; trajectories that
// do not meet at rest are refused.

#include "path/joined_path.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "reference_model.hpp"

namespace cyber::planner {
namespace {

const JointVector kStart{{0.5, 2.0}};
const JointVector kFirstDirection = JointVector{{0.6, 2.5}}.normalized();
constexpr double kFirstLength = 0.3;
const JointVector kJunction = kStart + kFirstLength * kFirstDirection;
const JointVector kSecondDirection = JointVector{{-0.2, 1.0}}.normalized();
constexpr double kSecondLength = 0.5;

std::shared_ptr<const StraightPath> firstPiece() {
  return std::make_shared<const StraightPath>(kStart, kFirstDirection, kFirstLength);
}
std::shared_ptr<const StraightPath> secondPiece() {
  return std::make_shared<const StraightPath>(kJunction, kSecondDirection, kSecondLength);
}

TEST(StraightPath, IsTheLineFromItsStartInClosedForm) {
  const StraightPath line(kStart, kFirstDirection, kFirstLength);
  EXPECT_EQ(line.length(), kFirstLength);
  for (int i = -2; i <= 12; ++i) {
    const double s = kFirstLength * i / 10;
    const PathPoint p = line.at(s);
    const double clamped = std::clamp(s, 0.0, kFirstLength);
    EXPECT_LT((p.q - (kStart + clamped * kFirstDirection)).norm(), 1e-15) << s;
    EXPECT_EQ(p.dq_ds, kFirstDirection);
    EXPECT_EQ(p.d2q_ds2, JointVector::Zero(2));
  }
}

TEST(JoinedPath, IsContinuousAtTheJunctionWhereTheSecondPieceAnswers) {
  const JoinedPath joined(firstPiece(), secondPiece());
  EXPECT_DOUBLE_EQ(joined.length(), kFirstLength + kSecondLength);
  EXPECT_EQ(joined.at(0.0).q, kStart);
  EXPECT_LT((joined.at(joined.length()).q - (kJunction + kSecondLength * kSecondDirection)).norm(), 1e-15);
  // Position is continuous across the junction; the tangent turns there, to the second piece's.
  const double split = kFirstLength;
  EXPECT_LT((joined.at(split - 1e-12).q - kJunction).norm(), 1e-11);
  EXPECT_LT((joined.at(split + 1e-12).q - kJunction).norm(), 1e-11);
  EXPECT_EQ(joined.at(split - 1e-12).dq_ds, kFirstDirection);
  EXPECT_EQ(joined.at(split).dq_ds, kSecondDirection);
  EXPECT_EQ(joined.at(split).q, secondPiece()->at(0.0).q);
  for (int i = 0; i <= 20; ++i) {
    const double s = joined.length() * i / 20;
    const PathPoint expected = s < split ? firstPiece()->at(s) : secondPiece()->at(s - split);
    EXPECT_EQ(joined.at(s).q, expected.q) << s;
  }
  // Beyond either end, clamped by the piece there.
  EXPECT_EQ(joined.at(-1.0).q, kStart);
  EXPECT_EQ(joined.at(joined.length() + 1.0).q, joined.at(joined.length()).q);
}

// Rest to rest on each piece, with uneven grids.
Result<Trajectory> onFirst(double b_end = 0.0) {
  return Trajectory::create(firstPiece(), test::referenceModel().driveModel(HeldPieces{}),
                            {0.0, 0.1, 0.25, kFirstLength}, {0.0, 0.4, 0.3, b_end});
}
Result<Trajectory> onSecond(double b_start = 0.0) {
  return Trajectory::create(secondPiece(), test::referenceModel().driveModel(HeldPieces{}),
                            {0.0, 0.2, 0.3, 0.45, kSecondLength}, {b_start, 0.5, 0.9, 0.2, 0.0});
}

TEST(JoinAtRest, ReplaysTheFirstThenTheSecondAndStopsAtTheJunction) {
  const auto first = onFirst(), second = onSecond();
  ASSERT_TRUE(first.ok() && second.ok());
  const auto joined = joinAtRest(first.value(), second.value());
  ASSERT_TRUE(joined.ok()) << joined.error().message;
  const Trajectory& t = joined.value();
  const double t1 = first.value().duration_s();
  EXPECT_NEAR(t.duration_s(), t1 + second.value().duration_s(), 1e-12);
  EXPECT_EQ(t.sGrid().size(), first.value().sGrid().size() + second.value().sGrid().size() - 1);
  for (int i = 0; i <= 40; ++i) {
    const double time = t.duration_s() * i / 40;
    const TrajectorySample s = t.sample(time);
    const TrajectorySample expected = time <= t1 ? first.value().sample(time) : second.value().sample(time - t1);
    EXPECT_LT((s.q - expected.q).norm(), 1e-9) << time;
    EXPECT_LT((s.qdot - expected.qdot).norm(), 1e-9) << time;
  }
  // Acceleration, constant on each interval, in the middle of every interval of the joined grid
  // (at a grid time it is one side's).
  const std::vector<double>& times = t.tGrid();
  for (size_t k = 0; k + 1 < times.size(); ++k) {
    const double time = 0.5 * (times[k] + times[k + 1]);
    const TrajectorySample expected = time <= t1 ? first.value().sample(time) : second.value().sample(time - t1);
    EXPECT_LT((t.sample(time).qddot - expected.qddot).norm(), 1e-7 * (1.0 + expected.qddot.norm())) << time;
  }
  // At rest at the junction, continuous in position and velocity on both sides of it.
  const TrajectorySample before = t.sample(t1 - 1e-9), at = t.sample(t1), after = t.sample(t1 + 1e-9);
  EXPECT_LT((at.q - kJunction).norm(), 1e-12);
  EXPECT_LT(at.qdot.norm(), 1e-12);
  EXPECT_LT((before.q - kJunction).norm(), 1e-9);
  EXPECT_LT((after.q - kJunction).norm(), 1e-9);
  EXPECT_LT(before.qdot.norm(), 1e-6);
  EXPECT_LT(after.qdot.norm(), 1e-6);
}

TEST(JoinAtRest, TrajectoriesThatDoNotMeetAtRestAreRefused) {
  const auto moving_end = onFirst(0.2), moving_start = onSecond(0.2), first = onFirst(), second = onSecond();
  ASSERT_TRUE(moving_end.ok() && moving_start.ok() && first.ok() && second.ok());
  for (const auto& [a, b] :
       {std::pair{&moving_end, &second}, std::pair{&first, &moving_start}, std::pair{&moving_end, &moving_start}}) {
    const auto joined = joinAtRest(a->value(), b->value());
    ASSERT_FALSE(joined.ok());
    EXPECT_EQ(joined.status(), PlanStatus::kInvalidInput);
    EXPECT_EQ(joined.error().message, "trajectories joined at rest must meet at rest");
  }
}

}  // namespace
}  // namespace cyber::planner

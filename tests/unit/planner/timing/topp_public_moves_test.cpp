// The acceptance test of the issue on the real paths: every public move the path stage plans is
// parameterised; the trajectory meets every limit at 1 ms within 0.5 %, starts and ends at the
// requested poses at rest, and its duration is within 2 % of a 2001-point forward-backward
// reference on the same path (testing::FineReference, independent of the solver).

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "path/path_planner.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"
#include "timing/topp.hpp"
#include "topp_fixtures.hpp"

namespace cyber::planner {
namespace {

TEST(ToppPublicMoves, EveryPlannedMoveMeetsTheLimitsAndTheReference) {
  const RobotModel& model = test::referenceModel();
  const PathPlanner planner(model, model.scenes.front());
  ToppSolver solver(model.planner.topp);
  int solved = 0;
  double worst_ratio = 0.0, worst_voltage = 0.0, worst_current = 0.0;
  for (const test::PublicMove& move : test::publicMoves()) {
    const auto planned = planner.plan(move.from, move.to, move.pieces);
    if (!planned.ok()) continue;  // the path stage's business (and tests)
    SCOPED_TRACE(move.label);
    const auto& path = planned.value().path;
    ToppReport report;
    const Result<Trajectory> result = solver.solve(path, model.driveModel({}), 0.0, &report);
    ASSERT_TRUE(result.ok()) << result.error().message;
    const Trajectory& trajectory = result.value();
    ++solved;

    EXPECT_LT((trajectory.sample(0.0).q - move.from).norm(), 1e-9);
    EXPECT_LT((trajectory.sample(trajectory.duration_s()).q - move.to).norm(), 1e-6);
    EXPECT_EQ(trajectory.sample(0.0).qdot, JointVector::Zero(2));
    EXPECT_LT(trajectory.sample(trajectory.duration_s()).qdot.norm(), 1e-6);

    const long n = static_cast<long>(trajectory.duration_s() / 0.001);
    for (long i = 0; i <= n + 1; ++i) {
      const TrajectorySample s = trajectory.sample(i <= n ? 0.001 * static_cast<double>(i) : trajectory.duration_s());
      for (int j = 0; j < 2; ++j) {
        const DriveParams& d = model.drive(j);
        const double v = d.volts(s.q[j], s.qdot[j], s.qddot[j]);
        worst_voltage = std::max(worst_voltage, std::abs(v) / d.voltage_limit_volts);
        worst_current = std::max(worst_current, std::abs(d.amps(v, s.qdot[j])) / d.current_limit_amps);
        ASSERT_LE(std::abs(v), 1.005 * d.voltage_limit_volts) << "t=" << s.t;
        ASSERT_LE(std::abs(d.amps(v, s.qdot[j])), 1.005 * d.current_limit_amps) << "t=" << s.t;
      }
    }
    const double reference = testing::FineReference(*path, model.drive(0), model.drive(1), 2001).duration(0.0);
    const double ratio = trajectory.duration_s() / reference;
    worst_ratio = std::max(worst_ratio, ratio);
    EXPECT_LE(ratio, 1.02) << trajectory.duration_s() << " s against " << reference << " s";
    EXPECT_GE(ratio, 0.995);
  }
  EXPECT_GT(solved, 100);  // the path stage plans most public moves
  RecordProperty("worst_duration_ratio", std::to_string(worst_ratio));
  RecordProperty("worst_voltage_ratio", std::to_string(worst_voltage));
  RecordProperty("worst_current_ratio", std::to_string(worst_current));
  std::printf("public moves: %d solved, worst duration/reference %.4f, peak |V|/Vmax %.4f, |I|/Imax %.4f\n", solved,
              worst_ratio, worst_voltage, worst_current);
}

}  // namespace
}  // namespace cyber::planner

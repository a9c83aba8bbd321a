// Time-optimal parameterisation: the acceptance tests of algorithm.md section 3 on analytic paths.
// Every trajectory is checked at 1 ms against every limit (0.5 %), at its ends, for kinematic
// consistency, and its duration against an independent fine-grid forward-backward reference.

#include "timing/topp.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "reference_model.hpp"
#include "topp_fixtures.hpp"

namespace cyber::planner {
namespace {

using testing::ArcPath;
using testing::armDrive;
using testing::drivesOf;
using testing::elevatorDrive;
using testing::FineReference;
using testing::LinePath;
using testing::referenceDrives;
using testing::WigglePath;

constexpr double kLimitTolerance = 0.005;    // the 0.5 %
constexpr double kDurationTolerance = 0.02;  // within 2 % of the fine reference
constexpr int kReferencePoints = 2001;

struct Checked {
  double peak_voltage_ratio = 0.0;
  double peak_current_ratio = 0.0;
  double peak_velocity_ratio = 0.0;
  double peak_acceleration_ratio = 0.0;
};

// Everything a trajectory must satisfy, checked at 1 ms independently of the solver's own check.
Checked checkTrajectory(const Trajectory& trajectory, const GeometricPath& path, const DriveParams& elevator,
                        const DriveParams& arm, double b_start) {
  Checked out;
  const DriveParams* drives[2] = {&elevator, &arm};
  const double duration = trajectory.duration_s();
  const PathPoint start = path.at(0.0);
  const PathPoint goal = path.at(path.length());

  const TrajectorySample first = trajectory.sample(0.0);
  const TrajectorySample last = trajectory.sample(duration);
  EXPECT_LT((first.q - start.q).norm(), 1e-12);
  EXPECT_LT((last.q - goal.q).norm(), 1e-9);
  EXPECT_LT((first.qdot - start.dq_ds * std::sqrt(b_start)).norm(), 1e-12) << "start velocity";
  EXPECT_LT(last.qdot.norm(), 1e-6) << "ends at rest";

  // Limits at 1 ms (and at the end).
  const long n = static_cast<long>(std::floor(duration / 0.001));
  for (long i = 0; i <= n + 1; ++i) {
    const TrajectorySample s = trajectory.sample(i <= n ? static_cast<double>(i) * 0.001 : duration);
    EXPECT_TRUE(s.q.allFinite() && s.qdot.allFinite() && s.qddot.allFinite());
    for (int j = 0; j < 2; ++j) {
      const DriveParams& d = *drives[j];
      // The feedforward re-derived from the model (independent of the sample's own fields).
      const double v = d.volts(s.q[j], s.qdot[j], s.qddot[j]);
      const double amps = d.amps(v, s.qdot[j]);
      EXPECT_NEAR(s.volts[j], v, 1e-9);
      EXPECT_NEAR(s.amps[j], amps, 1e-7);
      out.peak_voltage_ratio = std::max(out.peak_voltage_ratio, std::abs(v) / d.voltage_limit_volts);
      out.peak_current_ratio = std::max(out.peak_current_ratio, std::abs(amps) / d.current_limit_amps);
      if (d.velocity_limit) {
        out.peak_velocity_ratio = std::max(out.peak_velocity_ratio, std::abs(s.qdot[j]) / *d.velocity_limit);
      }
      if (d.acceleration_limit) {
        out.peak_acceleration_ratio =
            std::max(out.peak_acceleration_ratio, std::abs(s.qddot[j]) / *d.acceleration_limit);
      }
    }
  }
  // Kinematic consistency: trapezoidal integration of qdot and qddot at 0.1 ms (finer for short moves) reproduces q and
  // qdot (the acceleration jumps at grid points bound how exact the rule itself can be).
  TrajectorySample previous = first;
  JointVector integrated_q = first.q;
  JointVector integrated_qdot = first.qdot;
  double max_q_error = 0.0;
  double max_qdot_error = 0.0;
  double peak_speed = first.qdot.lpNorm<Eigen::Infinity>();
  const double fine_step = std::min(1e-4, duration / 2e4);
  const long fine = static_cast<long>(std::floor(duration / fine_step));
  for (long i = 1; i <= fine + 1; ++i) {
    const TrajectorySample s = trajectory.sample(i <= fine ? static_cast<double>(i) * fine_step : duration);
    const double h = s.t - previous.t;
    integrated_q += 0.5 * h * (s.qdot + previous.qdot);
    integrated_qdot += 0.5 * h * (s.qddot + previous.qddot);
    max_q_error = std::max(max_q_error, (integrated_q - s.q).lpNorm<Eigen::Infinity>());
    max_qdot_error = std::max(max_qdot_error, (integrated_qdot - s.qdot).lpNorm<Eigen::Infinity>());
    peak_speed = std::max(peak_speed, s.qdot.lpNorm<Eigen::Infinity>());
    previous = s;
  }
  const double travel = (goal.q - start.q).lpNorm<Eigen::Infinity>();
  EXPECT_LE(max_q_error, 1e-4 * std::max(travel, 1e-9) + 1e-12) << "velocity does not integrate to position";
  EXPECT_LE(max_qdot_error, 2e-3 * std::max(peak_speed, 1e-9) + 1e-12) << "acceleration does not integrate to velocity";
  EXPECT_LE(out.peak_voltage_ratio, 1.0 + kLimitTolerance);
  EXPECT_LE(out.peak_current_ratio, 1.0 + kLimitTolerance);
  EXPECT_LE(out.peak_velocity_ratio, 1.0 + kLimitTolerance);
  EXPECT_LE(out.peak_acceleration_ratio, 1.0 + kLimitTolerance);
  return out;
}

struct Case {
  std::string name;
  std::shared_ptr<const GeometricPath> path;
};

std::vector<Case> typicalPaths() {
  return {
      {"elevator up 0..2 m", std::make_shared<LinePath>(JointVector{{0.0, 1.57}}, JointVector{{2.0, 1.57}})},
      {"elevator down 2..0 m", std::make_shared<LinePath>(JointVector{{2.0, 1.57}}, JointVector{{0.0, 1.57}})},
      {"arm 0..6.1 rad", std::make_shared<LinePath>(JointVector{{0.6, 0.0}}, JointVector{{0.6, 6.1}})},
      {"arm 6.1..0 rad", std::make_shared<LinePath>(JointVector{{0.6, 6.1}}, JointVector{{0.6, 0.0}})},
      {"STOW->L4", std::make_shared<LinePath>(JointVector{{0.20, 1.57}}, JointVector{{1.97, 5.17}})},
      {"L4->PROCESSOR", std::make_shared<LinePath>(JointVector{{1.97, 5.17}}, JointVector{{0.16, 0.10}})},
      {"INTAKE->NET", std::make_shared<LinePath>(JointVector{{0.58, 2.97}}, JointVector{{1.93, 1.71}})},
      {"ALGAE_LOW->L2", std::make_shared<LinePath>(JointVector{{0.71, 0.10}}, JointVector{{0.73, 6.07}})},
      {"arc", std::make_shared<ArcPath>(JointVector{{1.0, 3.0}}, 0.8, 0.0, 3.0)},
      {"arc reversed", std::make_shared<ArcPath>(JointVector{{1.0, 3.0}}, 0.8, 3.0, -0.5)},
      {"S-curve, arm q' changes sign", std::make_shared<WigglePath>(JointVector{{0.2, 1.0}}, JointVector{{1.5, 4.0}},
                                                                    JointVector{{0.05, 0.8}}, 3.0, 2.0)},
      {"arm out and back", std::make_shared<WigglePath>(JointVector{{0.3, 2.0}}, JointVector{{1.3, 2.0}},
                                                        JointVector{{0.0, 1.0}}, 1.0, 1.2)},
      {"short 5 cm", std::make_shared<LinePath>(JointVector{{0.5, 1.0}}, JointVector{{0.55, 1.0}})},
  };
}

TEST(Topp, TypicalPathsMeetEveryLimitAndTheFineReference) {
  ToppSolver solver;
  for (const Case& c : typicalPaths()) {
    SCOPED_TRACE(c.name);
    ToppReport report;
    const Result<Trajectory> result = solver.solve(c.path, referenceDrives(), 0.0, &report);
    ASSERT_TRUE(result.ok()) << result.error().message;
    const Trajectory& trajectory = result.value();
    checkTrajectory(trajectory, *c.path, elevatorDrive(), armDrive(), 0.0);

    const double reference = FineReference(*c.path, elevatorDrive(), armDrive(), kReferencePoints).duration(0.0);
    ASSERT_TRUE(std::isfinite(reference));
    const double ratio = trajectory.duration_s() / reference;
    EXPECT_LE(ratio, 1.0 + kDurationTolerance) << "duration " << trajectory.duration_s() << " reference " << reference;
    EXPECT_GE(ratio, 1.0 - 0.005) << "faster than the reference: a limit is being cut";

    EXPECT_LE(report.primal_residual, ToppSettings{}.solver.primal_tolerance);
    EXPECT_LE(report.dual_residual, ToppSettings{}.solver.dual_tolerance);
    EXPECT_GE(report.outer_iterations, 1);
    EXPECT_GT(report.grid_points, 2);
  }
}

TEST(Topp, SolverReportsItsOwnCheckOfTheLimits) {
  const auto path = std::make_shared<LinePath>(JointVector{{0.20, 1.57}}, JointVector{{1.97, 5.17}});
  ToppReport report;
  const Result<Trajectory> result = parameterizeTimeOptimal(path, referenceDrives(), {}, 0.0, &report);
  ASSERT_TRUE(result.ok());
  const Checked checked = checkTrajectory(result.value(), *path, elevatorDrive(), armDrive(), 0.0);
  // A time-optimal move runs into its limits: both peaks are at the limit, not below it.
  EXPECT_NEAR(report.peak_voltage_ratio, checked.peak_voltage_ratio, 2e-3);
  EXPECT_NEAR(report.peak_current_ratio, checked.peak_current_ratio, 2e-3);
  EXPECT_GT(checked.peak_voltage_ratio, 0.99);
  EXPECT_GT(checked.peak_current_ratio, 0.99);
}

TEST(Topp, VelocityAndAccelerationLimitsHoldAtOneMillisecond) {
  DriveParams elevator = elevatorDrive();
  DriveParams arm = armDrive();
  elevator.velocity_limit = 1.2;  // m/s, well below the voltage-limited 2.9 m/s
  arm.acceleration_limit = 25.0;  // rad/s^2, well below the current-limited ~200 rad/s^2
  const auto path = std::make_shared<LinePath>(JointVector{{0.2, 0.5}}, JointVector{{1.9, 5.5}});
  const Result<Trajectory> result = parameterizeTimeOptimal(path, drivesOf(elevator, arm), {});
  ASSERT_TRUE(result.ok()) << result.error().message;
  const Checked checked = checkTrajectory(result.value(), *path, elevator, arm, 0.0);
  EXPECT_GT(checked.peak_velocity_ratio, 0.99);
  EXPECT_GT(checked.peak_acceleration_ratio, 0.99);
  // Slower than without these limits.
  const Result<Trajectory> free = parameterizeTimeOptimal(path, referenceDrives(), {});
  ASSERT_TRUE(free.ok());
  EXPECT_GT(result.value().duration_s(), 1.2 * free.value().duration_s());
}

// A velocity cap is active along most of a capped move. One row per grid point keeps the
// multipliers unique there (docs/algorithm.md section 3): with rows at the interval middles too,
// this move took 194 inner iterations (and its columns disagreed), now 1, and the caps hold at 1 ms.
TEST(Topp, VelocityCapsOverMostOfTheMoveSolveInFewIterations) {
  DriveParams elevator = elevatorDrive();
  DriveParams arm = armDrive();
  elevator.velocity_limit = 0.6;  // m/s: the daemon HIL tests' caps
  arm.velocity_limit = 1.5;       // rad/s
  const auto path = std::make_shared<WigglePath>(JointVector{{1.9, 5.1}}, JointVector{{0.2, 0.2}},
                                                 JointVector{{0.05, 0.4}}, 3.0, 2.5);
  ToppSolver solver;
  ToppReport report;
  const Result<Trajectory> result = solver.solve(path, drivesOf(elevator, arm), 0.0, &report);
  ASSERT_TRUE(result.ok()) << result.error().message;
  const Checked checked = checkTrajectory(result.value(), *path, elevator, arm, 0.0);
  EXPECT_GT(checked.peak_velocity_ratio, 0.99);
  EXPECT_LE(checked.peak_velocity_ratio, 1.0 + kLimitTolerance);
  EXPECT_LE(report.inner_iterations, 20);
}

TEST(Topp, MovingStartBeginsWithExactlyThatVelocity) {
  const auto path = std::make_shared<LinePath>(JointVector{{0.4, 1.0}}, JointVector{{1.8, 4.0}});
  ToppSolver solver;
  ToppReport rest_report;
  const Result<Trajectory> rest = solver.solve(path, referenceDrives(), 0.0, &rest_report);
  ASSERT_TRUE(rest.ok());
  ASSERT_GT(rest_report.controllable_start_b, 1.0);
  for (double fraction : {0.05, 0.3, 0.7, 0.999}) {
    SCOPED_TRACE(fraction);
    const double b_start = fraction * rest_report.controllable_start_b;
    const Result<Trajectory> moving = solver.solve(path, referenceDrives(), b_start);
    ASSERT_TRUE(moving.ok()) << moving.error().message;
    checkTrajectory(moving.value(), *path, elevatorDrive(), armDrive(), b_start);
    const TrajectorySample first = moving.value().sample(0.0);
    EXPECT_NEAR(first.sdot, std::sqrt(b_start), 1e-12);
    // |v0|_Sigma = sqrt(b_start) for a unit-speed path.
    EXPECT_NEAR(testing::weightedNorm(first.qdot), std::sqrt(b_start), 1e-9);
    EXPECT_LT(moving.value().duration_s(), rest.value().duration_s());
    const double reference = FineReference(*path, elevatorDrive(), armDrive(), kReferencePoints).duration(b_start);
    EXPECT_LE(moving.value().duration_s(), (1.0 + kDurationTolerance) * reference);
  }
}

TEST(Topp, StartSpeedThatCannotBeStoppedIsATypedFailure) {
  const auto path = std::make_shared<LinePath>(JointVector{{0.4, 1.0}}, JointVector{{0.6, 1.4}});
  ToppReport report;
  ToppSolver solver;
  ASSERT_TRUE(solver.solve(path, referenceDrives(), 0.0, &report).ok());
  const double limit = report.controllable_start_b;
  // The independent reference agrees on where the controllable set ends (within the grid error).
  EXPECT_NEAR(limit, FineReference(*path, elevatorDrive(), armDrive(), 501).controllableStart(), 0.03 * limit);
  const Result<Trajectory> too_fast = solver.solve(path, referenceDrives(), 1.5 * limit, &report);
  ASSERT_FALSE(too_fast.ok());
  EXPECT_EQ(too_fast.status(), PlanStatus::kInfeasibleStart);
  EXPECT_NE(too_fast.error().message.find("cannot be brought to rest"), std::string::npos) << too_fast.error().message;
  EXPECT_TRUE(solver.solve(path, referenceDrives(), 0.95 * limit).ok());
}

// A splice from one of the solver's own trajectories cruising at a limit can sit just past the new
// path's controllable set, because a trajectory may overshoot a limit by limit_check_tolerance
// (hil.daemon_motion caught b = 0.09175 against C_0 = 0.09166). Within that tolerance the start is
// planned from the fastest start that can be stopped; beyond it, it is refused.
TEST(Topp, StartJustPastTheControllableSetIsPlannedFromItsEdge) {
  const auto path = std::make_shared<LinePath>(JointVector{{0.4, 1.0}}, JointVector{{0.6, 1.4}});
  ToppSolver solver;
  ToppReport report;
  ASSERT_TRUE(solver.solve(path, referenceDrives(), 0.0, &report).ok());
  // C_0 of a moving start (a start at rest pins the first node to qdot = 0, which changes its rows).
  ASSERT_TRUE(solver.solve(path, referenceDrives(), 0.5 * report.controllable_start_b, &report).ok());
  EXPECT_EQ(report.start_speed_ratio, 1.0);
  const double limit = report.controllable_start_b;
  const double tolerance = ToppSettings{}.limit_check_tolerance;
  for (double speed_factor : {1.0005, 1.002, 0.999 + tolerance}) {
    SCOPED_TRACE(speed_factor);
    const double b_start = limit * speed_factor * speed_factor;
    const Result<Trajectory> result = solver.solve(path, referenceDrives(), b_start, &report);
    ASSERT_TRUE(result.ok()) << result.error().message;
    // The grid follows each start's own profile (algorithm.md section 3, "Grid"), so the edge
    // moves with the grid by far less than the tolerance; the start sits on this solve's edge.
    const double edge = report.controllable_start_b;
    EXPECT_NEAR(edge, limit, 1e-4 * limit);
    EXPECT_NEAR(report.start_speed_ratio, std::sqrt(edge / limit) / speed_factor, 1e-9);
    EXPECT_NEAR(result.value().sample(0.0).sdot, std::sqrt(edge), 1e-9);
    const Checked checked = checkTrajectory(result.value(), *path, elevatorDrive(), armDrive(), edge);
    EXPECT_LE(std::max(checked.peak_voltage_ratio, checked.peak_current_ratio), 1.0 + tolerance);
  }
  const double beyond = 1.001 + tolerance;
  const Result<Trajectory> too_fast = solver.solve(path, referenceDrives(), limit * beyond * beyond, &report);
  ASSERT_FALSE(too_fast.ok());
  EXPECT_EQ(too_fast.status(), PlanStatus::kInfeasibleStart);
  // Below the edge nothing changes: the start speed is the one asked for.
  ASSERT_TRUE(solver.solve(path, referenceDrives(), 0.99 * limit, &report).ok());
  EXPECT_EQ(report.start_speed_ratio, 1.0);
}

TEST(Topp, NonConvergenceIsReportedWithResiduals) {
  const auto path = std::make_shared<WigglePath>(JointVector{{0.2, 1.0}}, JointVector{{1.5, 4.0}},
                                                 JointVector{{0.05, 0.8}}, 3.0, 2.0);
  ToppSettings settings;
  settings.solver.max_outer_iterations = 1;
  settings.solver.max_inner_iterations = 2;
  settings.solver.primal_tolerance = 1e-15;
  settings.solver.dual_tolerance = 1e-15;
  ToppReport report;
  const Result<Trajectory> result = parameterizeTimeOptimal(path, referenceDrives(), settings, 0.0, &report);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status(), PlanStatus::kSolverNotConverged);
  EXPECT_NE(result.error().message.find("primal residual"), std::string::npos) << result.error().message;
  EXPECT_NE(result.error().message.find("dual residual"), std::string::npos);
  EXPECT_EQ(report.outer_iterations, 1);
  EXPECT_LE(report.inner_iterations, 2);
  EXPECT_GT(report.primal_residual + report.dual_residual, 0.0);
}

TEST(Topp, ConvergenceIsDecidedByResidualsNotByTheCap) {
  const auto path = std::make_shared<LinePath>(JointVector{{0.20, 1.57}}, JointVector{{1.97, 5.17}});
  ToppSettings settings;
  settings.solver.max_outer_iterations = 1000;
  ToppReport report;
  ASSERT_TRUE(parameterizeTimeOptimal(path, referenceDrives(), settings, 0.0, &report).ok());
  EXPECT_LT(report.outer_iterations, 20);
  EXPECT_LE(report.primal_residual, settings.solver.primal_tolerance);
  EXPECT_LE(report.dual_residual, settings.solver.dual_tolerance);
}

TEST(Topp, ZeroLengthPathIsAValidTrivialTrajectory) {
  const auto path = std::make_shared<LinePath>(JointVector{{0.7, 2.0}}, JointVector{{0.7, 2.0}});
  const Result<Trajectory> result = parameterizeTimeOptimal(path, referenceDrives(), {});
  ASSERT_TRUE(result.ok()) << result.error().message;
  EXPECT_EQ(result.value().duration_s(), 0.0);
  for (double t : {-1.0, 0.0, 0.5}) {
    const TrajectorySample s = result.value().sample(t);
    EXPECT_EQ(s.q, (JointVector{{0.7, 2.0}}));
    EXPECT_EQ(s.qdot, JointVector::Zero(2));
    EXPECT_NEAR(s.volts[test::kElevator], 0.37, 1e-12);  // holds against gravity
  }
  const Result<Trajectory> moving = parameterizeTimeOptimal(path, referenceDrives(), {}, 0.5);
  ASSERT_FALSE(moving.ok());
  EXPECT_EQ(moving.status(), PlanStatus::kInfeasibleStart);
}

TEST(Topp, VeryShortPathsGiveValidTrajectories) {
  for (double length : {1e-9, 1e-6, 1e-4, 1e-3, 1e-2}) {
    SCOPED_TRACE(length);
    const auto path = std::make_shared<LinePath>(JointVector{{0.5, 1.0}}, JointVector{{0.5 + length, 1.0}});
    const Result<Trajectory> result = parameterizeTimeOptimal(path, referenceDrives(), {});
    ASSERT_TRUE(result.ok()) << result.error().message;
    EXPECT_GT(result.value().duration_s(), 0.0);
    EXPECT_LT(result.value().duration_s(), 0.05);
    checkTrajectory(result.value(), *path, elevatorDrive(), armDrive(), 0.0);
    if (length >= 1e-4) {
      const double reference = FineReference(*path, elevatorDrive(), armDrive(), kReferencePoints).duration(0.0);
      EXPECT_LE(result.value().duration_s(), (1.0 + kDurationTolerance) * reference);
    }
  }
}

TEST(Topp, CoulombFrictionSwitchesSignWhereTheArmTurnsAround) {
  // The arm goes out and back while the elevator rises: q'_arm crosses zero mid-path.
  const auto path =
      std::make_shared<WigglePath>(JointVector{{0.3, 2.0}}, JointVector{{1.3, 2.0}}, JointVector{{0.0, 1.0}}, 1.0, 1.2);
  const Result<Trajectory> result = parameterizeTimeOptimal(path, referenceDrives(), {});
  ASSERT_TRUE(result.ok()) << result.error().message;
  const Trajectory& trajectory = result.value();
  checkTrajectory(trajectory, *path, elevatorDrive(), armDrive(), 0.0);
  // Find the turnaround and check the feedforward uses kS with the sign of the motion each side.
  const double turn_t = trajectory.timeAt(0.5 * path->length());
  const DriveParams arm = armDrive();
  for (double dt : {-0.004, 0.004}) {
    const TrajectorySample s = trajectory.sample(turn_t + dt);
    ASSERT_NE(s.qdot[test::kArm], 0.0);
    const double without_friction =
        arm.kG_volts * std::cos(s.q[test::kArm]) + arm.kV * s.qdot[test::kArm] + arm.kA * s.qddot[test::kArm];
    EXPECT_NEAR(s.volts[test::kArm] - without_friction, std::copysign(arm.kS_volts, s.qdot[test::kArm]), 1e-12);
  }
  EXPECT_GT(trajectory.sample(turn_t - 0.004).qdot[test::kArm], 0.0);
  EXPECT_LT(trajectory.sample(turn_t + 0.004).qdot[test::kArm], 0.0);
}

TEST(Topp, CoarseGridsAreRefinedUntilTheContinuousTrajectoryMeetsTheLimits) {
  const auto path = std::make_shared<WigglePath>(JointVector{{0.2, 1.0}}, JointVector{{1.5, 4.0}},
                                                 JointVector{{0.05, 0.8}}, 3.0, 2.0);
  ToppSettings settings;
  settings.grid_points = 12;
  ToppReport report;
  const Result<Trajectory> result = parameterizeTimeOptimal(path, referenceDrives(), settings, 0.0, &report);
  ASSERT_TRUE(result.ok()) << result.error().message;
  EXPECT_GT(report.refinements, 0);
  EXPECT_GT(report.grid_points, 12);
  checkTrajectory(result.value(), *path, elevatorDrive(), armDrive(), 0.0);
}

TEST(Topp, ResultsAreDeterministicAndTheSolverIsReusable) {
  const auto a = std::make_shared<ArcPath>(JointVector{{1.0, 3.0}}, 0.8, 0.0, 3.0);
  const auto b = std::make_shared<LinePath>(JointVector{{1.97, 5.17}}, JointVector{{0.16, 0.10}});
  ToppSolver reused;
  const double first = reused.solve(a, referenceDrives()).value().duration_s();
  const double other = reused.solve(b, referenceDrives()).value().duration_s();
  EXPECT_EQ(reused.solve(a, referenceDrives()).value().duration_s(), first);
  EXPECT_EQ(parameterizeTimeOptimal(b, referenceDrives(), {}).value().duration_s(), other);
}

// A path that returns garbage.
class BrokenPath final : public GeometricPath {
 public:
  explicit BrokenPath(double length) : length_(length) {}
  [[nodiscard]] double length() const override { return length_; }
  [[nodiscard]] PathPoint at(double) const override {
    PathPoint p;
    p.q = JointVector::Zero(2);
    p.dq_ds = JointVector{{std::numeric_limits<double>::quiet_NaN(), 1.0}};
    p.d2q_ds2 = JointVector::Zero(2);
    return p;
  }

 private:
  double length_;
};

TEST(Topp, BadInputsAreTypedErrors) {
  const auto good = std::make_shared<LinePath>(JointVector{{0.2, 1.0}}, JointVector{{1.0, 2.0}});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(parameterizeTimeOptimal(nullptr, referenceDrives(), {}).status(), PlanStatus::kInvalidInput);
  EXPECT_EQ(parameterizeTimeOptimal(good, referenceDrives(), {}, nan).status(), PlanStatus::kInvalidInput);
  EXPECT_EQ(parameterizeTimeOptimal(good, referenceDrives(), {}, -1.0).status(), PlanStatus::kInvalidInput);
  EXPECT_EQ(parameterizeTimeOptimal(std::make_shared<BrokenPath>(1.0), referenceDrives(), {}).status(),
            PlanStatus::kInvalidInput);
  EXPECT_EQ(parameterizeTimeOptimal(std::make_shared<BrokenPath>(nan), referenceDrives(), {}).status(),
            PlanStatus::kInvalidInput);
  DriveParams no_current = elevatorDrive();
  no_current.current_limit_amps = 0.0;
  EXPECT_EQ(parameterizeTimeOptimal(good, drivesOf(no_current, armDrive()), {}).status(), PlanStatus::kInvalidInput);
  DriveParams nan_gain = armDrive();
  nan_gain.kV = nan;
  EXPECT_EQ(parameterizeTimeOptimal(good, drivesOf(elevatorDrive(), nan_gain), {}).status(), PlanStatus::kInvalidInput);
  // Gravity alone above the voltage limit: no motion can follow the path.
  DriveParams weak = elevatorDrive();
  weak.kG_volts = 13.0;
  const Result<Trajectory> hopeless = parameterizeTimeOptimal(good, drivesOf(weak, armDrive()), {});
  EXPECT_EQ(hopeless.status(), PlanStatus::kInvalidInput);
  EXPECT_FALSE(hopeless.error().message.empty());
}

}  // namespace
}  // namespace cyber::planner

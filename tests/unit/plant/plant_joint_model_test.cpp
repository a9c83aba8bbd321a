// The joint model of cyber-plant-sim against closed-form solutions of the same ODE.

#include <gtest/gtest.h>

#include <cmath>

#include "cyber/plant/joint_model.hpp"
#include "reference_model.hpp"

namespace cyber::plant {
namespace {

using test::kArm;
using test::kElevator;

JointPlant referencePlant(int joint) {
  const auto& model = test::referenceModel();
  return JointPlant::fromDrive(model.drive(joint), model.range(joint));
}

JointState run(const JointPlant& plant, JointState state, double volts, double duration_s, double dt_s) {
  const long steps = std::lround(duration_s / dt_s);
  for (long i = 0; i < steps; ++i) state = stepPlant(plant, state, volts, dt_s);
  return state;
}

TEST(JointModel, CopiesTheDriveFigures) {
  const auto& drive = test::referenceModel().drive(1);
  const JointPlant plant = referencePlant(test::kArm);
  EXPECT_EQ(plant.kS_volts, drive.kS_volts);
  EXPECT_EQ(plant.kG_volts, drive.kG_volts);
  EXPECT_EQ(plant.kV, drive.kV);
  EXPECT_EQ(plant.kA, drive.kA);
  EXPECT_EQ(plant.voltage_limit_volts, drive.voltage_limit_volts);
  EXPECT_EQ(plant.range.max, test::referenceModel().range(1).max);
  EXPECT_DOUBLE_EQ(plant.gravityFactor(0.3), std::cos(0.3));
  EXPECT_EQ(referencePlant(test::kElevator).gravityFactor(0.3), 1.0);
}

// The feedforward of a constant velocity keeps that velocity: the model is the inverse of
// DriveParams::volts.
TEST(JointModel, FeedforwardOfAConstantVelocityHoldsIt) {
  const auto& drive = test::referenceModel().drive(0);
  const JointPlant plant = referencePlant(test::kElevator);
  for (double v : {-1.5, -0.2, 0.3, 2.0}) {
    JointState state{1.0, v};
    const double volts = drive.volts(state.position, v, 0.0);
    for (int i = 0; i < 100; ++i) state = stepPlant(plant, state, volts, 0.001);
    EXPECT_NEAR(state.velocity, v, 1e-12) << v;
    EXPECT_NEAR(state.position, 1.0 + v * 0.1, 1e-9) << v;
  }
}

// From rest under a constant voltage, kA v' = V - kS - kG - kV v: v(t) = v_inf (1 - exp(-t kV/kA)).
// Semi-implicit Euler is first order: the error shrinks in proportion to the step.
TEST(JointModel, ConstantVoltageMatchesTheExponentialToFirstOrder) {
  const JointPlant plant = referencePlant(test::kElevator);
  const double volts = 6.0;
  const double v_inf = (volts - plant.kS_volts - plant.kG_volts) / plant.kV;
  const double tau = plant.kA / plant.kV;
  const double t = 0.02;  // two time constants
  const double exact = v_inf * (1.0 - std::exp(-t / tau));
  double previous_error = 0.0;
  for (double dt : {1e-3, 5e-4, 2.5e-4}) {
    const JointState end = run(plant, JointState{0.5, 0.0}, volts, t, dt);
    const double error = std::abs(end.velocity - exact);
    EXPECT_LT(error, 0.05 * v_inf) << dt;
    if (previous_error > 0.0) {
      EXPECT_NEAR(previous_error / error, 2.0, 0.3) << dt;
    }
    previous_error = error;
  }
  // And it settles at v_inf.
  EXPECT_NEAR(run(plant, JointState{0.5, 0.0}, volts, 0.5, 1e-3).velocity, v_inf, 1e-9);
}

TEST(JointModel, StictionHoldsAJointAtRestWithinTheFrictionBand) {
  const JointPlant plant = referencePlant(test::kElevator);
  for (double dv : {-0.999 * plant.kS_volts, -0.05, 0.0, 0.1, 0.999 * plant.kS_volts}) {
    const JointState end = run(plant, JointState{0.7, 0.0}, plant.kG_volts + dv, 0.5, 1e-3);
    EXPECT_EQ(end.position, 0.7) << dv;
    EXPECT_EQ(end.velocity, 0.0) << dv;
  }
  // Just past the band it moves, in the direction of the pull.
  EXPECT_GT(run(plant, JointState{0.7, 0.0}, plant.kG_volts + plant.kS_volts + 0.01, 0.1, 1e-3).position, 0.7);
  EXPECT_LT(run(plant, JointState{0.7, 0.0}, plant.kG_volts - plant.kS_volts - 0.01, 0.1, 1e-3).position, 0.7);
}

// Without gravity and drive, a moving joint decelerates under kS and kV and stops for good,
// never reversing. Closed form: v(t) = (v0 + kS/kV) exp(-t kV/kA) - kS/kV until v = 0, and the
// distance travelled is kA/kV (v0 - kS/kV ln(1 + v0 kV/kS)).
TEST(JointModel, FrictionStopsAJointWithoutReversingIt) {
  JointPlant plant = referencePlant(test::kElevator);
  plant.kG_volts = 0.0;
  const double v0 = 0.8;
  const double s = plant.kS_volts / plant.kV;
  const double distance = plant.kA / plant.kV * (v0 - s * std::log(1.0 + v0 / s));
  JointState state{1.0, v0};
  for (int i = 0; i < 1000; ++i) {
    state = stepPlant(plant, state, 0.0, 1e-4);
    ASSERT_GE(state.velocity, 0.0);
  }
  EXPECT_EQ(state.velocity, 0.0);
  EXPECT_NEAR(state.position - 1.0, distance, 0.02 * distance);
}

// Neutral (0 V, brake mode): the elevator slides down at (kG - kS) / kV; the arm near vertical
// (cos ~ 0) stays put because friction beats gravity there.
TEST(JointModel, NeutralSlidesAtTheBrakeVelocityOrStaysPut) {
  const JointPlant elevator = referencePlant(test::kElevator);
  const double slide = neutralSlideVelocity(elevator, 1.0);
  EXPECT_NEAR(slide, -(elevator.kG_volts - elevator.kS_volts) / elevator.kV, 1e-15);
  const JointState end = run(elevator, JointState{1.0, 0.0}, 0.0, 0.3, 1e-3);
  EXPECT_NEAR(end.velocity, slide, 1e-9);

  const JointPlant arm = referencePlant(test::kArm);
  EXPECT_EQ(neutralSlideVelocity(arm, 1.57), 0.0);
  EXPECT_EQ(run(arm, JointState{1.57, 0.0}, 0.0, 0.5, 1e-3).position, 1.57);
  // Horizontal, pointing forward: gravity (cos 0 = 1) beats friction, it falls (theta decreases).
  EXPECT_LT(neutralSlideVelocity(arm, 0.5), 0.0);
  EXPECT_LT(run(arm, JointState{0.5, 0.0}, 0.0, 0.1, 1e-3).position, 0.5);
  // Pointing backward (cos < 0) it falls the other way.
  EXPECT_GT(neutralSlideVelocity(arm, 3.0), 0.0);
}

TEST(JointModel, HardStopsAtTheJointRange) {
  const JointPlant plant = referencePlant(test::kElevator);
  JointState state{0.05, 0.0};
  for (int i = 0; i < 500; ++i) {
    state = stepPlant(plant, state, -plant.voltage_limit_volts, 1e-3);
    ASSERT_GE(state.position, plant.range.min);
  }
  EXPECT_EQ(state.position, plant.range.min);
  EXPECT_EQ(state.velocity, 0.0);
  state = JointState{plant.range.max - 0.05, 0.0};
  for (int i = 0; i < 500; ++i) {
    state = stepPlant(plant, state, plant.voltage_limit_volts, 1e-3);
    ASSERT_LE(state.position, plant.range.max);
  }
  EXPECT_EQ(state.position, plant.range.max);
  EXPECT_EQ(state.velocity, 0.0);
  // Pulling away from a stop moves off it.
  state = stepPlant(plant, state, -plant.voltage_limit_volts, 1e-3);
  EXPECT_LT(state.velocity, 0.0);
}

TEST(JointModel, ControllerIsFeedforwardPlusPdClampedToTheLimit) {
  const JointPlant plant = referencePlant(test::kArm);
  const PdGains gains{60.0, 0.1};
  const JointCommand command{1.0, 0.5, 0.7};
  const JointState state{0.99, 0.4};
  EXPECT_NEAR(controllerVolts(plant, gains, command, state), 0.7 + 60.0 * 0.01 + 0.1 * 0.1, 1e-12);
  EXPECT_EQ(controllerVolts(plant, gains, JointCommand{2.0, 0.0, 0.0}, state), plant.voltage_limit_volts);
  EXPECT_EQ(controllerVolts(plant, gains, JointCommand{0.0, 0.0, 0.0}, state), -plant.voltage_limit_volts);
  EXPECT_EQ(controllerVolts(plant, PdGains{}, JointCommand{0.0, 0.0, 30.0}, state), plant.voltage_limit_volts);
}

}  // namespace
}  // namespace cyber::plant

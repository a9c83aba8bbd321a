// The plant simulator's mechanism: the planner's drive model read backwards, on every shipped
// robot (feedforward per joint and coupled rigid-body; chains of one, two and three joints), and
// closed-form solutions of the single-joint ODE on the reference robot.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "cyber/config/load_config.hpp"
#include "cyber/plant/mechanism_plant.hpp"
#include "reference_model.hpp"

namespace cyber::plant {
namespace {

using planner::JointVector;
using test::kArm;
using test::kElevator;

const std::vector<std::string>& shippedRobots() {
  static const std::vector<std::string> names{"reefscape-2025", "chargedup-2023-double-jointed", "pivot-telescope",
                                              "intake-pivot", "reefscape-2025-elevator-pivot-wrist"};
  return names;
}

const planner::RobotModel& shippedRobot(const std::string& name) {
  static std::map<std::string, planner::RobotModel> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    it = cache.emplace(name, config::loadConfigFile(std::string(CYBER_SOURCE_DIR) + "/config/" + name + ".toml").robot)
             .first;
  }
  return it->second;
}

MechanismPlant referencePlant() { return MechanismPlant::fromRobot(test::referenceModel()); }

MechanismState run(const MechanismPlant& plant, MechanismState state, const JointVector& volts, double duration_s,
                   double dt_s, JointFlags latched = {}) {
  const long steps = std::lround(duration_s / dt_s);
  for (long i = 0; i < steps; ++i) state = plant.step(state, volts, dt_s, latched);
  return state;
}

JointVector randomPose(const planner::RobotModel& robot, std::mt19937& rng) {
  JointVector q(robot.jointCount());
  for (int j = 0; j < robot.jointCount(); ++j) {
    q[j] = std::uniform_real_distribution<double>(robot.range(j).min, robot.range(j).max)(rng);
  }
  return q;
}

// The middle of every joint's range.
JointVector middlePose(const planner::RobotModel& robot) {
  JointVector q(robot.jointCount());
  for (int j = 0; j < robot.jointCount(); ++j) q[j] = 0.5 * (robot.range(j).min + robot.range(j).max);
  return q;
}

TEST(MechanismPlant, HasOneJointPerJointOfTheChain) {
  for (const auto& [name, joints] : std::vector<std::pair<std::string, int>>{
           {"reefscape-2025", 2}, {"intake-pivot", 1}, {"reefscape-2025-elevator-pivot-wrist", 3}}) {
    const planner::RobotModel& robot = shippedRobot(name);
    ASSERT_EQ(robot.jointCount(), joints) << name;
    const MechanismPlant plant = MechanismPlant::fromRobot(robot);
    EXPECT_EQ(plant.jointCount(), joints) << name;
    for (int j = 0; j < joints; ++j) {
      EXPECT_EQ(plant.range(j).min, robot.range(j).min) << name << " joint " << j;
      EXPECT_EQ(plant.range(j).max, robot.range(j).max) << name << " joint " << j;
    }
    const MechanismState next = plant.step(MechanismState::atRest(middlePose(robot)), JointVector::Zero(joints), 1e-3);
    EXPECT_EQ(next.q.size(), joints) << name;
    EXPECT_EQ(next.qdot.size(), joints) << name;
  }
}

// The plant is the inverse of DriveModel::volts: applying the voltage the planner computes for
// (q, v, a) accelerates the simulated mechanism by a, coupling terms included.
TEST(MechanismPlant, AcceleratesAsThePlannerModelSaysOnEveryShippedRobot) {
  for (const std::string& name : shippedRobots()) {
    const planner::RobotModel& robot = shippedRobot(name);
    const MechanismPlant plant = MechanismPlant::fromRobot(robot);
    std::mt19937 rng(7);
    for (int trial = 0; trial < 200; ++trial) {
      // Away from the stops, moving (stiction is a separate case).
      MechanismState state = MechanismState::atRest(randomPose(robot, rng));
      JointVector a(robot.jointCount());
      for (int j = 0; j < robot.jointCount(); ++j) {
        const double span = robot.range(j).max - robot.range(j).min;
        state.q[j] = std::clamp(state.q[j], robot.range(j).min + 0.1 * span, robot.range(j).max - 0.1 * span);
        state.qdot[j] = std::uniform_real_distribution<double>(0.2, 2.0)(rng) * (trial % 2 == 0 ? 1.0 : -1.0);
        a[j] = std::uniform_real_distribution<double>(-20.0, 20.0)(rng);
      }
      const JointVector volts = plant.drive().volts(state.q, state.qdot, a);
      // Short enough that the back-EMF the step takes implicitly, an O(dt) term that the coupling
      // carries to a joint of small acceleration (the three-joint wrist), stays far inside the
      // tolerance.
      const double dt = 1e-8;
      const MechanismState next = plant.step(state, volts, dt);
      const JointVector measured = (next.qdot - state.qdot) / dt;
      ASSERT_EQ(next.q.size(), robot.jointCount()) << name;
      for (int j = 0; j < robot.jointCount(); ++j) {
        ASSERT_NEAR(measured[j], a[j], 1e-3 * (1.0 + std::abs(a[j]))) << name << " trial " << trial << " joint " << j;
      }
    }
  }
}

// With any joints latched (at rest, not moving this step), the free ones still accelerate as the
// planner's model says for an acceleration that is zero on the latched ones, whatever voltage the
// latched ones get: the free joints' rows of the coupled system are solved alone (on three joints,
// a middle joint latched leaves joints 0 and 2).
TEST(MechanismPlant, AcceleratesAsThePlannerModelSaysWithAnyJointsLatched) {
  for (const std::string& name : shippedRobots()) {
    const planner::RobotModel& robot = shippedRobot(name);
    const MechanismPlant plant = MechanismPlant::fromRobot(robot);
    const int n = robot.jointCount();
    std::mt19937 rng(11);
    // Every set of latched joints but all of them (bit j: joint j latched).
    for (unsigned mask = 0; mask + 1 < (1U << n); ++mask) {
      JointFlags latched{};
      for (int j = 0; j < n; ++j) latched[static_cast<size_t>(j)] = ((mask >> j) & 1U) != 0;
      for (int trial = 0; trial < 20; ++trial) {
        MechanismState state = MechanismState::atRest(randomPose(robot, rng));
        JointVector a = JointVector::Zero(n);
        for (int j = 0; j < n; ++j) {
          const double span = robot.range(j).max - robot.range(j).min;
          state.q[j] = std::clamp(state.q[j], robot.range(j).min + 0.1 * span, robot.range(j).max - 0.1 * span);
          if (latched[static_cast<size_t>(j)]) continue;
          state.qdot[j] = std::uniform_real_distribution<double>(0.2, 2.0)(rng) * (trial % 2 == 0 ? 1.0 : -1.0);
          a[j] = std::uniform_real_distribution<double>(-20.0, 20.0)(rng);
        }
        JointVector volts = plant.drive().volts(state.q, state.qdot, a);
        // A latched joint's own voltage moves nothing: its row is out of the solve.
        for (int j = 0; j < n; ++j) {
          if (latched[static_cast<size_t>(j)]) volts[j] += trial % 2 == 0 ? 3.0 : -3.0;
        }
        // Short enough that the back-EMF the step takes implicitly, an O(dt) term that the coupling
        // carries to a joint of small acceleration (the three-joint wrist), stays far inside the
        // tolerance.
        const double dt = 1e-8;
        const MechanismState next = plant.step(state, volts, dt, latched);
        for (int j = 0; j < n; ++j) {
          if (latched[static_cast<size_t>(j)]) {
            EXPECT_EQ(next.q[j], state.q[j]) << name << " latched " << mask << " joint " << j;
            EXPECT_EQ(next.qdot[j], 0.0) << name << " latched " << mask << " joint " << j;
          } else {
            ASSERT_NEAR((next.qdot[j] - state.qdot[j]) / dt, a[j], 1e-3 * (1.0 + std::abs(a[j])))
                << name << " latched " << mask << " trial " << trial << " joint " << j;
          }
        }
      }
    }
  }
}

// The one-joint intake pivot (config/intake-pivot.toml) in neutral: pointing forward, gravity beats
// friction and it swings down, onto its lower hard stop where it stays; near vertical friction
// holds it.
TEST(MechanismPlant, OneJointPivotFallsOntoItsStopInNeutral) {
  const planner::RobotModel& robot = shippedRobot("intake-pivot");
  ASSERT_EQ(robot.jointCount(), 1);
  const MechanismPlant plant = MechanismPlant::fromRobot(robot);
  const JointVector forward{{0.3}};
  EXPECT_LT(neutralSlideVelocity(plant, 0, forward), 0.0);
  EXPECT_GT(neutralSlideVelocity(plant, 0, (JointVector{{2.5}})), 0.0);  // leaning back: falls back
  EXPECT_EQ(neutralSlideVelocity(plant, 0, (JointVector{{M_PI / 2}})), 0.0);
  // Geared 50:1, the back-EMF of brake mode lets it swing down only slowly, at about the balance
  // speed of where it is.
  MechanismState state = run(plant, MechanismState::atRest(forward), JointVector::Zero(1), 1.0, 1e-3);
  EXPECT_LT(state.q[0], forward[0] - 0.05);
  EXPECT_NEAR(state.qdot[0], neutralSlideVelocity(plant, 0, state.q), 0.05 * std::abs(state.qdot[0]));
  // Near the lower stop it lands on it and stays.
  state = MechanismState::atRest(JointVector{{plant.range(0).min + 0.03}});
  for (int i = 0; i < 2000; ++i) {
    state = plant.step(state, JointVector::Zero(1), 1e-3);
    ASSERT_GE(state.q[0], plant.range(0).min);
  }
  EXPECT_EQ(state.q[0], plant.range(0).min);
  EXPECT_EQ(state.qdot[0], 0.0);
  const MechanismState upright =
      run(plant, MechanismState::atRest(JointVector{{M_PI / 2}}), JointVector::Zero(1), 0.5, 1e-3);
  EXPECT_EQ(upright.q[0], M_PI / 2);
}

// The feedforward of a constant velocity, re-evaluated as the pose changes, keeps that velocity.
TEST(MechanismPlant, FeedforwardOfAConstantVelocityHoldsItOnEveryShippedRobot) {
  for (const std::string& name : shippedRobots()) {
    const planner::RobotModel& robot = shippedRobot(name);
    const MechanismPlant plant = MechanismPlant::fromRobot(robot);
    const int n = robot.jointCount();
    MechanismState state = MechanismState::atRest(middlePose(robot));
    JointVector v(n);
    for (int j = 0; j < n; ++j) v[j] = j % 2 == 0 ? 0.3 : -0.4;
    state.qdot = v;
    for (int i = 0; i < 100; ++i) {
      state = plant.step(state, plant.drive().volts(state.q, state.qdot, JointVector::Zero(n)), 0.001);
    }
    for (int j = 0; j < n; ++j) EXPECT_NEAR(state.qdot[j], v[j], 1e-9) << name << " joint " << j;
  }
}

// One joint from rest under a constant voltage, the other latched: kA v' = V - kS - kG - kV v, so
// v(t) = v_inf (1 - exp(-t kV/kA)). Semi-implicit Euler is first order: the error halves with the step.
TEST(MechanismPlant, ConstantVoltageMatchesTheExponentialToFirstOrder) {
  const MechanismPlant plant = referencePlant();
  const planner::DriveParams& drive = plant.drive().drive(kElevator);
  const double volts = 6.0;
  const double v_inf = (volts - drive.kS_volts - drive.kG_volts) / drive.kV;
  const double tau = drive.kA / drive.kV;
  const double t = 0.02;  // two time constants
  const double exact = v_inf * (1.0 - std::exp(-t / tau));
  const MechanismState start{JointVector{{0.5, 1.57}}, JointVector::Zero(2)};
  const JointVector applied{{volts, 0.0}};
  double previous_error = 0.0;
  for (double dt : {1e-3, 5e-4, 2.5e-4}) {
    const MechanismState end = run(plant, start, applied, t, dt, {false, true});
    const double error = std::abs(end.qdot[kElevator] - exact);
    EXPECT_LT(error, 0.05 * v_inf) << dt;
    if (previous_error > 0.0) {
      EXPECT_NEAR(previous_error / error, 2.0, 0.3) << dt;
    }
    previous_error = error;
    EXPECT_EQ(end.q[kArm], start.q[kArm]);  // latched
  }
  EXPECT_NEAR(run(plant, start, applied, 0.5, 1e-3, {false, true}).qdot[kElevator], v_inf, 1e-9);
}

TEST(MechanismPlant, StictionHoldsAJointAtRestWithinTheFrictionBand) {
  const MechanismPlant plant = referencePlant();
  const planner::DriveParams& drive = plant.drive().drive(kElevator);
  const MechanismState start{JointVector{{0.7, 1.57}}, JointVector::Zero(2)};
  for (double dv : {-0.999 * drive.kS_volts, -0.05, 0.0, 0.1, 0.999 * drive.kS_volts}) {
    const MechanismState end = run(plant, start, JointVector{{drive.kG_volts + dv, 0.0}}, 0.5, 1e-3, {false, true});
    EXPECT_EQ(end.q[kElevator], 0.7) << dv;
    EXPECT_EQ(end.qdot[kElevator], 0.0) << dv;
  }
  // Just past the band it moves, in the direction of the pull.
  EXPECT_GT(run(plant, start, (JointVector{{drive.kG_volts + drive.kS_volts + 0.01, 0.0}}), 0.1, 1e-3, {false, true})
                .q[kElevator],
            0.7);
  EXPECT_LT(run(plant, start, (JointVector{{drive.kG_volts - drive.kS_volts - 0.01, 0.0}}), 0.1, 1e-3, {false, true})
                .q[kElevator],
            0.7);
}

// Without gravity and drive, a moving joint decelerates under kS and kV and stops for good, never
// reversing: v(t) = (v0 + kS/kV) exp(-t kV/kA) - kS/kV until v = 0, and the distance travelled is
// kA/kV (v0 - kS/kV ln(1 + v0 kV/kS)).
TEST(MechanismPlant, FrictionStopsAJointWithoutReversingIt) {
  const planner::RobotModel& robot = test::referenceModel();
  auto drives = robot.drives;
  drives[kElevator].kG_volts = 0.0;
  const MechanismPlant plant(planner::DriveModel(robot.joints, drives), {robot.range(0), robot.range(1)});
  const planner::DriveParams& drive = drives[kElevator];
  const double v0 = 0.8;
  const double s = drive.kS_volts / drive.kV;
  const double distance = drive.kA / drive.kV * (v0 - s * std::log(1.0 + v0 / s));
  MechanismState state{JointVector{{1.0, 1.57}}, JointVector{{v0, 0.0}}};
  for (int i = 0; i < 1000; ++i) {
    state = plant.step(state, JointVector::Zero(2), 1e-4, {false, true});
    ASSERT_GE(state.qdot[kElevator], 0.0);
  }
  EXPECT_EQ(state.qdot[kElevator], 0.0);
  EXPECT_NEAR(state.q[kElevator] - 1.0, distance, 0.02 * distance);
}

// Neutral (0 V, brake mode): the elevator slides down at (kG - kS) / kV; the arm near vertical
// (cos ~ 0) stays put because friction beats gravity there, and falls where gravity wins.
TEST(MechanismPlant, NeutralSlidesAtTheBrakeVelocityOrStaysPut) {
  const MechanismPlant plant = referencePlant();
  const planner::DriveParams& elevator = plant.drive().drive(kElevator);
  const double slide = neutralSlideVelocity(plant, kElevator, JointVector{{1.0, 1.57}});
  EXPECT_NEAR(slide, -(elevator.kG_volts - elevator.kS_volts) / elevator.kV, 1e-12);
  const MechanismState start{JointVector{{1.0, 1.57}}, JointVector::Zero(2)};
  const MechanismState end = run(plant, start, JointVector::Zero(2), 0.3, 1e-3);
  EXPECT_NEAR(end.qdot[kElevator], slide, 1e-9);
  EXPECT_EQ(end.q[kArm], 1.57);  // near vertical, friction holds it

  EXPECT_EQ(neutralSlideVelocity(plant, kArm, (JointVector{{1.0, 1.57}})), 0.0);
  // Horizontal, pointing forward: gravity beats friction, it falls (theta decreases).
  EXPECT_LT(neutralSlideVelocity(plant, kArm, (JointVector{{1.0, 0.5}})), 0.0);
  EXPECT_LT(run(plant, MechanismState{(JointVector{{1.0, 0.5}}), JointVector::Zero(2)}, JointVector::Zero(2), 0.1, 1e-3,
                {true, false})
                .q[kArm],
            0.5);
  // Pointing backward it falls the other way.
  EXPECT_GT(neutralSlideVelocity(plant, kArm, (JointVector{{1.0, 3.0}})), 0.0);
}

TEST(MechanismPlant, HardStopsAtTheJointRange) {
  const MechanismPlant plant = referencePlant();
  const double limit = plant.voltageLimit(kElevator);
  const planner::JointRange& range = plant.range(kElevator);
  MechanismState state{JointVector{{range.min + 0.05, 1.57}}, JointVector::Zero(2)};
  for (int i = 0; i < 500; ++i) {
    state = plant.step(state, JointVector{{-limit, 0.0}}, 1e-3, {false, true});
    ASSERT_GE(state.q[kElevator], range.min);
  }
  EXPECT_EQ(state.q[kElevator], range.min);
  EXPECT_EQ(state.qdot[kElevator], 0.0);
  state = MechanismState{JointVector{{range.max - 0.05, 1.57}}, JointVector::Zero(2)};
  for (int i = 0; i < 500; ++i) {
    state = plant.step(state, JointVector{{limit, 0.0}}, 1e-3, {false, true});
    ASSERT_LE(state.q[kElevator], range.max);
  }
  EXPECT_EQ(state.q[kElevator], range.max);
  EXPECT_EQ(state.qdot[kElevator], 0.0);
  // Pulling away from a stop moves off it.
  state = plant.step(state, JointVector{{-limit, 0.0}}, 1e-3, {false, true});
  EXPECT_LT(state.qdot[kElevator], 0.0);
}

TEST(MechanismPlant, ControllerIsFeedforwardPlusPdClampedToTheLimit) {
  const PdGains gains{60.0, 0.1};
  const JointCommand command{1.0, 0.5, 0.7};
  EXPECT_NEAR(controllerVolts(12.0, gains, command, 0.99, 0.4), 0.7 + 60.0 * 0.01 + 0.1 * 0.1, 1e-12);
  EXPECT_EQ(controllerVolts(12.0, gains, JointCommand{2.0, 0.0, 0.0}, 0.99, 0.4), 12.0);
  EXPECT_EQ(controllerVolts(12.0, gains, JointCommand{0.0, 0.0, 0.0}, 0.99, 0.4), -12.0);
  EXPECT_EQ(controllerVolts(12.0, PdGains{}, JointCommand{0.0, 0.0, 30.0}, 0.99, 0.4), 12.0);
}

// Gains from the drive, not per robot: on the reference drives (WPILib feedforward, so a = kA and
// d = kV exactly) a double pole at -w where kV < 2 w kA (the elevator), else Kd = 0 and the slower
// pole at -w (the arm).
TEST(MechanismPlant, DerivedGainsPlaceThePolesAtTheBandwidth) {
  const MechanismPlant plant = referencePlant();
  const double w = 100.0;
  for (int joint : {kElevator, kArm}) {
    const planner::DriveParams& drive = plant.drive().drive(joint);
    const PdGains gains = derivedGains(plant, joint, w);
    const double damping = drive.kV + gains.kd_volts_per_unit_per_s;
    // The slower root of kA s^2 + damping s + Kp.
    const double discriminant = damping * damping - 4.0 * drive.kA * gains.kp_volts_per_unit;
    EXPECT_GE(discriminant, -1e-9 * damping * damping) << joint;
    const double slow_pole = (-damping + std::sqrt(std::max(0.0, discriminant))) / (2.0 * drive.kA);
    EXPECT_NEAR(slow_pole, -w, 1e-3 * w) << joint;
  }
  EXPECT_GT(derivedGains(plant, kElevator, w).kd_volts_per_unit_per_s, 0.0);
  EXPECT_EQ(derivedGains(plant, kArm, w).kd_volts_per_unit_per_s, 0.0);
}

// On every shipped robot, each joint with derived gains recovers from a 10 mm (or 10 mrad) offset
// without overshooting past the friction band, and settles within it in 10 time constants.
TEST(MechanismPlant, DerivedGainsSettleEveryShippedJointWithoutOvershoot) {
  constexpr double kBandwidth_radps = 100.0;
  for (const std::string& name : shippedRobots()) {
    const planner::RobotModel& robot = shippedRobot(name);
    const MechanismPlant plant = MechanismPlant::fromRobot(robot);
    const int n = robot.jointCount();
    for (int joint = 0; joint < n; ++joint) {
      const PdGains gains = derivedGains(plant, joint, kBandwidth_radps);
      const JointVector target = middlePose(robot);
      const JointVector hold_volts = plant.drive().volts(target, JointVector::Zero(n), JointVector::Zero(n));
      const double band = plant.drive().drive(joint).kS_volts / gains.kp_volts_per_unit;
      MechanismState state = MechanismState::atRest(target);
      state.q[joint] -= 0.01;
      JointFlags latched{};
      for (int j = 0; j < n; ++j) latched[static_cast<size_t>(j)] = j != joint;  // the others held
      double overshoot = 0.0;
      for (int i = 0; i < 100; ++i) {  // 0.1 s = 10 / w
        JointVector volts = hold_volts;
        volts[joint] =
            controllerVolts(plant.voltageLimit(joint), gains, JointCommand{target[joint], 0.0, hold_volts[joint]},
                            state.q[joint], state.qdot[joint]);
        state = plant.step(state, volts, 0.001, latched);
        overshoot = std::max(overshoot, state.q[joint] - target[joint]);
      }
      EXPECT_LE(overshoot, band + 1e-4) << name << " joint " << joint;
      EXPECT_LE(std::abs(state.q[joint] - target[joint]), band + 1e-4) << name << " joint " << joint;
    }
  }
}

}  // namespace
}  // namespace cyber::plant

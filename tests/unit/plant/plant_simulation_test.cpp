// PlantSimulation: each joint tracking a setpoint stream like the daemon's, timeouts, disables; on
// the two-joint reference robot, the double-jointed arm, and chains of one and three joints.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "cyber/config/load_config.hpp"
#include "cyber/planner.hpp"
#include "cyber/plant/plant_simulation.hpp"
#include "reference_model.hpp"

namespace cyber::plant {
namespace {

using test::kArm;
using test::kElevator;

constexpr double kStreamPeriod_s = 0.005;  // the daemon's default 200 Hz

SimulationSettings referenceSettings() { return SimulationSettings(MechanismPlant::fromRobot(test::referenceModel())); }

// Where stiction can hold a joint under hold setpoints (feedforward kG g(target)): the spring Kp e
// must beat kS plus the gravity difference kG |g(q) - g(target)| <= kG |g'| e, with |g'| <= 1 for
// the cosine and 0 for the constant model.
double deadBand(const SimulationSettings& settings, int joint) {
  const planner::DriveParams& drive = settings.plant.drive().drive(joint);
  const double gravity_slope = drive.gravity == planner::GravityModel::kCosine ? drive.kG_volts : 0.0;
  return drive.kS_volts / (settings.gains[joint].kp_volts_per_unit - gravity_slope) + 1e-9;
}

// A rest-to-rest quintic move q0 -> q1 in duration_s: position, velocity, acceleration at t.
struct Quintic {
  double q0, q1, duration_s;
  void sample(double t, double& q, double& v, double& a) const {
    const double s = std::clamp(t / duration_s, 0.0, 1.0);
    const double d = q1 - q0;
    q = q0 + d * s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);
    v = d * 30.0 * s * s * (1.0 - s) * (1.0 - s) / duration_s;
    a = d * 60.0 * s * (1.0 - s) * (1.0 - 2.0 * s) / (duration_s * duration_s);
  }
};

JointCommand commandAt(const Quintic& move, const planner::DriveParams& drive, double t) {
  double q, v, a;
  move.sample(t, q, v, a);
  return JointCommand{q, v, drive.volts(q, v, a)};
}

struct TrackingResult {
  double max_error[2] = {0.0, 0.0};
  double final_error[2] = {0.0, 0.0};
};

// Streams both moves at 200 Hz (then hold setpoints until end_s), stepping the simulation between
// frames, and records the position error against the planned position at each frame.
TrackingResult track(PlantSimulation& sim, const Quintic (&moves)[2], double end_s) {
  const auto& model = test::referenceModel();
  TrackingResult result;
  for (long k = 0; k * kStreamPeriod_s <= end_s + 1e-12; ++k) {
    const double t = static_cast<double>(k) * kStreamPeriod_s;
    for (int joint : {test::kElevator, test::kArm}) {
      const JointCommand command = commandAt(moves[joint], model.drive(joint), t);
      sim.receiveSetpoint(joint, command, t);
      const double error = std::abs(sim.state(joint).position - command.position);
      result.max_error[joint] = std::max(result.max_error[joint], error);
      result.final_error[joint] = std::abs(sim.state(joint).position - moves[joint].q1);
    }
  }
  return result;
}

TEST(PlantSimulation, TracksAFeedforwardMoveAndSettlesWithinTheFrictionBand) {
  PlantSimulation sim(referenceSettings(), planner::JointVector{{0.2, 1.57}});
  const Quintic moves[2] = {{0.2, 1.5, 1.0}, {1.57, 5.0, 1.0}};
  const TrackingResult result = track(sim, moves, 1.5);
  // The plant is the feedforward model itself, so only integration and extrapolation errors
  // remain during the move (measured: 0.6 mm and 1.1 mrad).
  EXPECT_LT(result.max_error[test::kElevator], 0.001);
  EXPECT_LT(result.max_error[test::kArm], 0.002);
  // At rest the PD loop leaves at most the friction dead band.
  EXPECT_LE(result.final_error[test::kElevator], deadBand(sim.settings(), test::kElevator));
  EXPECT_LE(result.final_error[test::kArm], deadBand(sim.settings(), test::kArm));
  EXPECT_NEAR(sim.velocities()[test::kElevator], 0.0, 1e-6);
  EXPECT_NEAR(sim.velocities()[test::kArm], 0.0, 1e-6);
}

// Feedback matters: from a start 5 cm / 0.2 rad off, hold setpoints pull both joints to within
// the friction band, for seeded random targets across the range.
TEST(PlantSimulation, HoldSetpointsConvergeFromAnOffsetStart) {
  const auto& model = test::referenceModel();
  std::mt19937 rng(20250611);
  std::uniform_real_distribution<double> elevator(0.1, 1.9);
  std::uniform_real_distribution<double> arm(0.3, 5.8);
  for (int trial = 0; trial < 20; ++trial) {
    // The arm's target is drawn first: the seeded targets this test has always used.
    const double arm_target = arm(rng);
    const planner::JointVector target{{elevator(rng), arm_target}};
    PlantSimulation sim(referenceSettings(), target + planner::JointVector{{-0.05, 0.2}});
    for (long k = 0; k <= 200; ++k) {
      const double t = static_cast<double>(k) * kStreamPeriod_s;
      for (int joint : {test::kElevator, test::kArm}) {
        const JointCommand hold{target[joint], 0.0, model.drive(joint).volts(target[joint], 0.0, 0.0)};
        sim.receiveSetpoint(joint, hold, t);
      }
    }
    for (int joint : {test::kElevator, test::kArm}) {
      EXPECT_LE(std::abs(sim.positions()[joint] - target[joint]), deadBand(sim.settings(), joint))
          << "trial " << trial << " joint " << joint;
    }
  }
}

TEST(PlantSimulation, StepsOnAFixedGridAndNeverGoesBack) {
  PlantSimulation sim(referenceSettings(), planner::JointVector{{0.2, 1.57}});
  EXPECT_EQ(sim.time_s(), 0.0);
  sim.advanceTo(0.0);
  EXPECT_EQ(sim.time_s(), 0.0);
  sim.advanceTo(0.0001);
  EXPECT_DOUBLE_EQ(sim.time_s(), 0.001);  // the step starting at 0 ran
  sim.advanceTo(0.0105);
  EXPECT_DOUBLE_EQ(sim.time_s(), 0.011);
  sim.advanceTo(0.003);
  EXPECT_DOUBLE_EQ(sim.time_s(), 0.011);
  sim.advanceTo(0.012);  // on the grid: exactly there, despite 0.012 / 0.001 rounding
  EXPECT_DOUBLE_EQ(sim.time_s(), 0.012);
  for (int k = 13; k < 1000; ++k) {
    sim.advanceTo(k * 0.001);
    ASSERT_DOUBLE_EQ(sim.time_s(), k * 0.001) << k;
  }
}

TEST(PlantSimulation, IsDeterministic) {
  const Quintic moves[2] = {{0.2, 1.0, 0.8}, {1.57, 3.0, 0.8}};
  PlantSimulation a(referenceSettings(), planner::JointVector{{0.2, 1.57}});
  PlantSimulation b(referenceSettings(), planner::JointVector{{0.2, 1.57}});
  track(a, moves, 1.0);
  track(b, moves, 1.0);
  EXPECT_EQ(a.positions(), b.positions());
  EXPECT_EQ(a.velocities(), b.velocities());
}

TEST(PlantSimulation, ExtrapolatesTheLatestSetpointUntilItTimesOut) {
  PlantSimulation sim(referenceSettings(), planner::JointVector{{0.2, 1.57}});
  EXPECT_FALSE(sim.effectiveCommand(test::kElevator, 0.0));  // nothing received: neutral
  sim.receiveSetpoint(test::kElevator, JointCommand{0.3, 0.5, 2.0}, 1.0);
  const auto at = sim.effectiveCommand(test::kElevator, 1.004);
  ASSERT_TRUE(at);
  EXPECT_DOUBLE_EQ(at->position, 0.3 + 0.5 * 0.004);
  EXPECT_EQ(at->velocity, 0.5);
  EXPECT_EQ(at->feedforward_volts, 2.0);
  EXPECT_TRUE(sim.effectiveCommand(test::kElevator, 1.0999));
  EXPECT_FALSE(sim.effectiveCommand(test::kElevator, 1.1001));
  EXPECT_FALSE(sim.effectiveCommand(test::kArm, 1.0));  // per joint
}

// Setpoints stop (the daemon stopped streaming): after the timeout the controller is neutral and
// the elevator slides down under gravity in brake mode, as a real one would.
TEST(PlantSimulation, GoesNeutralAfterTheSetpointTimeout) {
  const auto& model = test::referenceModel();
  PlantSimulation sim(referenceSettings(), planner::JointVector{{1.0, 1.57}});
  const JointCommand hold{1.0, 0.0, model.drive(0).volts(1.0, 0.0, 0.0)};
  for (int k = 0; k < 20; ++k) sim.receiveSetpoint(test::kElevator, hold, k * kStreamPeriod_s);
  const double last_s = 19 * kStreamPeriod_s;
  sim.advanceTo(last_s + 0.099);
  EXPECT_NE(sim.appliedVolts(test::kElevator), 0.0);
  EXPECT_NEAR(sim.positions()[test::kElevator], 1.0, 0.001);
  sim.advanceTo(last_s + 0.3);
  EXPECT_EQ(sim.appliedVolts(test::kElevator), 0.0);
  EXPECT_NEAR(sim.velocities()[test::kElevator],
              neutralSlideVelocity(sim.settings().plant, test::kElevator, (planner::JointVector{{1.0, 1.57}})), 1e-6);
  EXPECT_LT(sim.positions()[test::kElevator], 0.995);
}

TEST(PlantSimulation, RestsAtTheInitialPoseUntilTheFirstSetpoint) {
  PlantSimulation sim(referenceSettings(), planner::JointVector{{1.0, 0.3}});
  sim.advanceTo(2.0);  // gravity would pull both down in neutral
  EXPECT_EQ(sim.positions(), (planner::JointVector{{1.0, 0.3}}));
  EXPECT_EQ(sim.velocities(), (planner::JointVector{{0.0, 0.0}}));
  // A setpoint for the elevator only: the elevator is driven, the arm still rests.
  sim.receiveSetpoint(test::kElevator, JointCommand{1.0, 0.0, 0.37}, 2.0);
  sim.advanceTo(2.5);  // past the timeout: neutral, sliding
  EXPECT_LT(sim.positions()[test::kElevator], 0.99);
  EXPECT_EQ(sim.positions()[test::kArm], 0.3);
}

TEST(PlantSimulation, BroadcastDisableIsNeutralAtOnceUntilTheNextSetpoint) {
  PlantSimulation sim(referenceSettings(), planner::JointVector{{1.0, 1.57}});
  sim.receiveSetpoint(test::kElevator, JointCommand{1.0, 0.0, 0.37}, 0.0);
  sim.receiveSetpoint(test::kArm, JointCommand{1.57, 0.0, 0.0}, 0.0);
  sim.advanceTo(0.01);
  sim.disableOutputs();
  EXPECT_FALSE(sim.effectiveCommand(test::kElevator, 0.011));
  EXPECT_FALSE(sim.effectiveCommand(test::kArm, 0.011));
  sim.advanceTo(0.02);
  EXPECT_EQ(sim.appliedVolts(test::kElevator), 0.0);
  sim.receiveSetpoint(test::kElevator, JointCommand{1.0, 0.0, 0.37}, 0.02);
  EXPECT_TRUE(sim.effectiveCommand(test::kElevator, 0.021));
  EXPECT_FALSE(sim.effectiveCommand(test::kArm, 0.021));  // only the joint that got a setpoint
}

// The double-jointed arm, whose shoulder load depends on the elbow (coupled rigid-body drive): a
// planned move streamed as the daemon streams it (200 Hz, the trajectory's feedforward, holding
// the goal afterwards) is tracked closely and settles within the friction band. The plant is the
// planner's own model, so what is left is integration, extrapolation and the PD loop.
TEST(PlantSimulation, TracksAPlannedMoveOfTheDoubleJointedArm) {
  const config::Config config =
      config::loadConfigFile(std::string(CYBER_SOURCE_DIR) + "/config/chargedup-2023-double-jointed.toml");
  const auto planner = planner::MotionPlanner::create(config.robot, planner::GridSelection{0, 0.0});
  ASSERT_TRUE(planner.ok());
  planner::JointVector from, to;
  for (const auto& set : config.poses) {
    if (set.name != "none") continue;
    for (const auto& pose : set.poses) {
      if (pose.name == "HOMED") from = pose.q;
      if (pose.name == "DOUBLE_SUBSTATION") to = pose.q;
    }
  }
  planner::PlanRequest request;
  request.start = from;
  request.goal = to;
  const auto plan = planner.value().plan(request);
  ASSERT_TRUE(plan.ok());
  const planner::Trajectory& trajectory = *plan.value().trajectory;

  const SimulationSettings settings(MechanismPlant::fromRobot(config.robot));
  PlantSimulation sim(settings, from);
  const double end_s = trajectory.duration_s() + 0.5;
  double max_error[2] = {0.0, 0.0};
  for (long k = 0; k * kStreamPeriod_s <= end_s + 1e-12; ++k) {
    const double t = static_cast<double>(k) * kStreamPeriod_s;
    // After the end, the daemon's hold setpoints: the goal with the voltage that holds it at rest.
    planner::TrajectorySample s;
    if (t < trajectory.duration_s()) {
      s = trajectory.sample(t);
    } else {
      s.q = to;
      s.qdot = planner::JointVector::Zero(to.size());
      s.volts = settings.plant.drive().volts(to, s.qdot, s.qdot);
    }
    for (int joint = 0; joint < sim.jointCount(); ++joint) {
      sim.receiveSetpoint(joint, JointCommand{s.q[joint], s.qdot[joint], s.volts[joint]}, t);
      max_error[joint] = std::max(max_error[joint], std::abs(sim.positions()[joint] - s.q[joint]));
    }
  }
  for (int joint = 0; joint < sim.jointCount(); ++joint) {
    EXPECT_LT(max_error[joint], 0.005) << joint;  // measured 1.5 and 2.2 mrad
    const double band = settings.plant.drive().drive(joint).kS_volts / settings.gains[joint].kp_volts_per_unit;
    EXPECT_LE(std::abs(sim.positions()[joint] - to[joint]), 2.0 * band + 1e-5) << joint;
  }
  std::cout << "max tracking error " << max_error[0] << ", " << max_error[1] << " rad; final "
            << sim.positions()[0] - to[0] << ", " << sim.positions()[1] - to[1] << "\n";
}

config::Config shippedConfig(const std::string& name) {
  return config::loadConfigFile(std::string(CYBER_SOURCE_DIR) + "/config/" + name + ".toml");
}

planner::JointVector namedPose(const config::Config& config, const std::string& name) {
  for (const auto& set : config.poses) {
    if (set.name != "none") continue;
    for (const auto& pose : set.poses) {
      if (pose.name == name) return pose.q;
    }
  }
  ADD_FAILURE() << "no pose " << name;
  return planner::JointVector::Zero(config.robot.jointCount());
}

struct ChainTracking {
  std::vector<double> max_error;     // per joint, against the commanded position at each frame
  std::vector<double> max_ff_share;  // per joint: the largest |feedforward| over the voltage limit
  planner::JointVector final_q;
};

// Every joint moves from `from` to `to` on a rest-to-rest quintic in duration_s, streamed at 200 Hz
// with the coupled feedforward of the plant's drive (DriveModel::volts of the whole chain, as the
// daemon's trajectories carry it), then held at `to` with the voltage that holds it for hold_s.
ChainTracking trackChain(PlantSimulation& sim, const planner::JointVector& from, const planner::JointVector& to,
                         double duration_s, double hold_s) {
  const int n = sim.jointCount();
  const planner::DriveModel& drive = sim.settings().plant.drive();
  ChainTracking result{std::vector<double>(static_cast<size_t>(n), 0.0),
                       std::vector<double>(static_cast<size_t>(n), 0.0), planner::JointVector::Zero(n)};
  for (long k = 0; k * kStreamPeriod_s <= duration_s + hold_s + 1e-12; ++k) {
    const double t = static_cast<double>(k) * kStreamPeriod_s;
    planner::JointVector q(n), v(n), a(n);
    for (int j = 0; j < n; ++j) Quintic{from[j], to[j], duration_s}.sample(t, q[j], v[j], a[j]);
    const planner::JointVector volts = drive.volts(q, v, a);
    for (int j = 0; j < n; ++j) {
      const auto index = static_cast<size_t>(j);
      sim.receiveSetpoint(j, JointCommand{q[j], v[j], volts[j]}, t);
      result.max_error[index] = std::max(result.max_error[index], std::abs(sim.positions()[j] - q[j]));
      result.max_ff_share[index] =
          std::max(result.max_ff_share[index], std::abs(volts[j]) / sim.settings().plant.voltageLimit(j));
    }
  }
  result.final_q = sim.positions();
  return result;
}

// The one-joint intake pivot (config/intake-pivot.toml) and the three-joint elevator, pivot and
// wrist (config/reefscape-2025-elevator-pivot-wrist.toml), each coupled rigid body: a move of every
// joint at once, inside the voltage limits, is tracked closely and settles within twice the
// friction band (the others' coupling adds to each joint's share, as on the double-jointed arm).
TEST(PlantSimulation, TracksAMoveOfChainsOfOneAndThreeJoints) {
  struct Case {
    const char* robot;
    const char* from;
    const char* to;
    int joints;
    double max_error;  // m or rad
  };
  for (const Case& c : {Case{"intake-pivot", "STOW", "DEPLOYED", 1, 0.005},
                        Case{"reefscape-2025-elevator-pivot-wrist", "STOW", "L4", 3, 0.005},
                        Case{"reefscape-2025-elevator-pivot-wrist", "L4", "PROCESSOR", 3, 0.005}}) {
    const config::Config config = shippedConfig(c.robot);
    ASSERT_EQ(config.robot.jointCount(), c.joints) << c.robot;
    const SimulationSettings settings(MechanismPlant::fromRobot(config.robot));
    ASSERT_EQ(settings.gains.size(), c.joints) << c.robot;
    const planner::JointVector from = namedPose(config, c.from);
    const planner::JointVector to = namedPose(config, c.to);
    PlantSimulation sim(settings, from);
    const ChainTracking result = trackChain(sim, from, to, 1.5, 0.5);
    ASSERT_EQ(result.final_q.size(), c.joints);
    for (int j = 0; j < c.joints; ++j) {
      const auto index = static_cast<size_t>(j);
      const std::string label = std::string(c.robot) + " " + c.from + "->" + c.to + " joint " + std::to_string(j);
      ASSERT_LT(result.max_ff_share[index], 1.0) << label;  // the controller never clamps the feedforward
      EXPECT_LT(result.max_error[index], c.max_error) << label;
      const double band = settings.plant.drive().drive(j).kS_volts / settings.gains[j].kp_volts_per_unit;
      EXPECT_LE(std::abs(result.final_q[j] - to[j]), 2.0 * band + 1e-5) << label;
      std::cout << label << ": max tracking error " << result.max_error[index] << ", final "
                << result.final_q[j] - to[j] << ", feedforward up to " << result.max_ff_share[index]
                << " of the limit\n";
    }
  }
}

// Three controllers, three streams: a setpoint for one joint drives that joint only (the others
// rest at the initial pose until their own first setpoint), and a broadcast disable sends all
// three neutral.
TEST(PlantSimulation, EachOfThreeJointsFollowsItsOwnStream) {
  const config::Config config = shippedConfig("reefscape-2025-elevator-pivot-wrist");
  ASSERT_EQ(config.robot.jointCount(), 3);
  const SimulationSettings settings(MechanismPlant::fromRobot(config.robot));
  const planner::JointVector stow = namedPose(config, "STOW");
  PlantSimulation sim(settings, stow);
  EXPECT_EQ(sim.jointCount(), 3);
  planner::JointVector target = stow;
  target[2] += 0.3;  // the wrist (joint 2) only
  const planner::JointVector hold_volts =
      settings.plant.drive().volts(target, planner::JointVector::Zero(3), planner::JointVector::Zero(3));
  for (long k = 0; k <= 100; ++k) {
    sim.receiveSetpoint(2, JointCommand{target[2], 0.0, hold_volts[2]}, static_cast<double>(k) * kStreamPeriod_s);
  }
  EXPECT_EQ(sim.positions()[0], stow[0]);
  EXPECT_EQ(sim.positions()[1], stow[1]);
  EXPECT_NEAR(sim.positions()[2], target[2], 2e-3);
  EXPECT_FALSE(sim.effectiveCommand(0, sim.time_s()));
  EXPECT_TRUE(sim.effectiveCommand(2, sim.time_s()));
  EXPECT_NE(sim.appliedVolts(2), 0.0);
  EXPECT_EQ(sim.appliedVolts(0), 0.0);

  for (int j = 0; j < 3; ++j) sim.receiveSetpoint(j, JointCommand{target[j], 0.0, hold_volts[j]}, 0.505);
  sim.advanceTo(0.51);
  for (int j = 0; j < 3; ++j) EXPECT_TRUE(sim.effectiveCommand(j, 0.51)) << j;
  sim.disableOutputs();
  for (int j = 0; j < 3; ++j) EXPECT_FALSE(sim.effectiveCommand(j, 0.511)) << j;
  sim.advanceTo(0.52);
  for (int j = 0; j < 3; ++j) EXPECT_EQ(sim.appliedVolts(j), 0.0) << j;
}

}  // namespace
}  // namespace cyber::plant

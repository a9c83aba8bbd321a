// The drive model (chain.hpp, docs/algorithm.md section 3) against the formulas written out by
// hand: WPILib's feedforward V = kS sgn(qdot) + kG f(psi) + kV qdot + kA qddot with psi read off
// the chain's own frames, a DC motor's current (V - G qdot / Kv) / R, the rigid-body kind against
// the chain's dynamics, and the path form of both against the volts of the motion along the path.

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "cyber/planner/chain.hpp"

namespace cyber::planner {
namespace {

constexpr double kPi = std::numbers::pi;

MotorParams krakenX60() {
  MotorParams m;
  m.nominal_voltage_volts = 12.0;
  m.stall_torque_nm = 7.09;
  m.stall_current_amps = 366.0;
  m.free_current_amps = 2.0;
  m.free_speed_radps = 6000.0 * 2.0 * kPi / 60.0;
  return m;
}

DriveParams drive(GravityModel gravity, double ks, double kg, double kv, double ka) {
  DriveParams d;
  d.motor = krakenX60();
  d.motor_count = 2;
  d.gearing = 45.0;
  d.kS_volts = ks;
  d.kG_volts = kg;
  d.kV = kv;
  d.kA = ka;
  d.gravity = gravity;
  d.current_limit_amps = 60.0;
  return d;
}

double sgn(double v) { return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0); }

// The motor's figures as WPILib's DCMotor derives them.
double resistance(const MotorParams& m) { return m.nominal_voltage_volts / m.stall_current_amps; }
double kv(const MotorParams& m) {
  return m.free_speed_radps / (m.nominal_voltage_volts - resistance(m) * m.free_current_amps);
}
double kt(const MotorParams& m) { return m.stall_torque_nm / m.stall_current_amps; }

// Two draws in order (a constructor's arguments are evaluated in an unspecified order: the targets
// would draw different vectors).
JointVector draw(std::uniform_real_distribution<double>& d, std::mt19937& rng) {
  const double first = d(rng);
  return JointVector{{first, d(rng)}};
}

// A chain of each pair of joint types, with seeded origins and axes.
std::vector<JointChain> everyJointTypePair(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), axis(-kPi, kPi);
  std::vector<JointChain> chains;
  for (const JointType first : {JointType::kPrismatic, JointType::kRevolute}) {
    for (const JointType second : {JointType::kPrismatic, JointType::kRevolute}) {
      JointChain& chain = chains.emplace_back(2);
      const double x0 = u(rng), y0 = u(rng), axis0 = axis(rng), x1 = u(rng), y1 = u(rng), axis1 = axis(rng);
      chain[0] = ChainJoint{"first", first, Point2(x0, y0), axis0, {-3.0, 3.0}};
      chain[1] = ChainJoint{"second", second, Point2(x1, y1), axis1, {-3.0, 3.0}};
    }
  }
  return chains;
}

TEST(DriveParams, VoltsAreWpilibsFeedforwardForEveryGravityModel) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-5.0, 5.0), angle(-kPi, kPi);
  const struct {
    GravityModel model;
    double (*factor)(double);
  } kModels[] = {{GravityModel::kConstant, [](double) { return 1.0; }},
                 {GravityModel::kCosine, [](double psi) { return std::cos(psi); }},
                 {GravityModel::kSine, [](double psi) { return std::sin(psi); }},
                 {GravityModel::kNone, [](double) { return 0.0; }}};
  for (const auto& m : kModels) {
    const DriveParams d = drive(m.model, 0.17, 0.42, 2.3, 0.07);
    for (int i = 0; i < 200; ++i) {
      const double psi = angle(rng), qdot = i % 10 == 0 ? 0.0 : u(rng), qddot = u(rng);
      EXPECT_DOUBLE_EQ(d.gravityFactor(psi), m.factor(psi));
      const double expected = 0.17 * sgn(qdot) + 0.42 * m.factor(psi) + 2.3 * qdot + 0.07 * qddot;
      EXPECT_NEAR(d.volts(psi, qdot, qddot), expected, 1e-12) << "psi " << psi << " qdot " << qdot;
    }
  }
  // At rest kS pushes neither way: holding needs the gravity term alone.
  EXPECT_DOUBLE_EQ(drive(GravityModel::kConstant, 0.17, 0.42, 2.3, 0.07).volts(0.3, 0.0, 0.0), 0.42);
}

TEST(DriveParams, AmpsAreTheDcMotorsCurrentPerMotor) {
  const DriveParams d = drive(GravityModel::kNone, 0.0, 0.0, 0.0, 0.0);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> volts(-12.0, 12.0), qdot(-3.0, 3.0);
  for (int i = 0; i < 200; ++i) {
    const double v = volts(rng), w = qdot(rng);
    // V = I R + omega / Kv with omega the motor's speed, G times the joint's.
    EXPECT_NEAR(d.amps(v, w), (v - 45.0 * w / kv(d.motor)) / resistance(d.motor), 1e-9);
  }
  // Stalled at the nominal voltage: the stall current; at free speed with no load: the free current.
  EXPECT_NEAR(d.amps(12.0, 0.0), 366.0, 1e-9);
  EXPECT_NEAR(d.amps(12.0, d.motor.free_speed_radps / 45.0), 2.0, 1e-9);
}

// psi of a revolute joint is its link's x axis in the world, of a prismatic joint its direction of
// travel: both read here from the chain's frames (chain.hpp), for every pair of joint types.
TEST(DriveModel, GravityAngleIsTheJointsDirectionInTheWorld) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> q(-2.0, 2.0);
  for (const JointChain& chain : everyJointTypePair(rng)) {
    const DriveModel drives(chain, {drive(GravityModel::kCosine, 0, 1, 0, 0), drive(GravityModel::kSine, 0, 1, 0, 0)});
    EXPECT_EQ(drives.kind(), DriveKind::kFeedforward);
    for (int i = 0; i < 50; ++i) {
      const JointVector at = draw(q, rng);
      const ChainPose pose = chainPose(chain, at);
      for (int j = 0; j < 2; ++j) {
        const Point2 direction = chain[static_cast<size_t>(j)].type == JointType::kRevolute
                                     ? pose.frames[static_cast<size_t>(j)].rotate(Point2(1.0, 0.0))
                                     : pose.travel[static_cast<size_t>(j)];
        const double psi = drives.gravityAngle(j, at);
        EXPECT_NEAR(std::cos(psi), direction.x(), 1e-12) << "joint " << j;
        EXPECT_NEAR(std::sin(psi), direction.y(), 1e-12) << "joint " << j;
      }
    }
  }
}

TEST(DriveModel, FeedforwardVoltsAndAmpsAreEachJointsOwn) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  const JointChain chain = everyJointTypePair(rng)[1];  // an arm on an elevator
  const PerJoint<DriveParams> params{drive(GravityModel::kSine, 0.15, 0.37, 3.93, 0.038),
                                     drive(GravityModel::kCosine, 0.2, 0.21, 1.18, 0.0056)};
  const DriveModel drives(chain, params);
  for (int i = 0; i < 100; ++i) {
    const JointVector q = draw(u, rng), qdot = draw(u, rng), qddot = draw(u, rng);
    const JointVector volts = drives.volts(q, qdot, qddot);
    const JointVector amps = drives.amps(volts, qdot);
    for (int j = 0; j < 2; ++j) {
      const DriveParams& d = params[static_cast<size_t>(j)];
      const double psi = drives.gravityAngle(j, q);
      const double f = d.gravity == GravityModel::kSine ? std::sin(psi) : std::cos(psi);
      EXPECT_NEAR(volts[j], d.kS_volts * sgn(qdot[j]) + d.kG_volts * f + d.kV * qdot[j] + d.kA * qddot[j], 1e-12);
      EXPECT_NEAR(amps[j], (volts[j] - d.gearing * qdot[j] / kv(d.motor)) / resistance(d.motor), 1e-9);
    }
  }
}

// The rigid-body kind: the joint's torque from the chain's dynamics, shared by its motors through
// the gearing, V = kS sgn(qdot) + R tau / (Kt G n) + G qdot / Kv; kG, kV and kA play no part.
TEST(DriveModel, RigidBodyVoltsAreTheChainsTorqueThroughTheMotors) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (const JointChain& chain : everyJointTypePair(rng)) {
    const ChainDynamics dynamics(chain,
                                 {LinkInertia{3.0, Point2(0.3, 0.05), 0.1}, LinkInertia{1.5, Point2(0.2, -0.1), 0.04}});
    PerJoint<DriveParams> params{drive(GravityModel::kCosine, 0.15, 9.0, 9.0, 9.0),
                                 drive(GravityModel::kConstant, 0.25, 9.0, 9.0, 9.0)};
    params[1].motor_count = 1;
    params[1].gearing = 120.0;
    const DriveModel drives(params, dynamics);
    EXPECT_EQ(drives.kind(), DriveKind::kRigidBody);
    for (int i = 0; i < 50; ++i) {
      const JointVector q = draw(u, rng), qdot = draw(u, rng), qddot = draw(u, rng);
      const JointVector tau = dynamics.torque(q, qdot, qddot);
      const JointVector volts = drives.volts(q, qdot, qddot);
      const JointVector amps = drives.amps(volts, qdot);
      for (int j = 0; j < 2; ++j) {
        const DriveParams& d = params[static_cast<size_t>(j)];
        const MotorParams& m = d.motor;
        const double expected = d.kS_volts * sgn(qdot[j]) +
                                resistance(m) * tau[j] / (kt(m) * d.gearing * d.motor_count) +
                                d.gearing * qdot[j] / kv(m);
        EXPECT_NEAR(volts[j], expected, 1e-9 * (1.0 + std::abs(expected)));
        // Beyond what kS draws, each motor's current is its share of the torque: Kt I n G = tau.
        const double load_amps = amps[j] - d.kS_volts * sgn(qdot[j]) / resistance(m);
        EXPECT_NEAR(load_amps * kt(m) * d.gearing * d.motor_count, tau[j], 1e-9 * (1.0 + std::abs(tau[j])));
      }
    }
  }
}

// Along a path, qdot = q' sqrt(b) and qddot = q' a + q'' b: the path coefficients of either kind
// give the volts of that motion (kS aside), and the current times R without the back-EMF term.
TEST(DriveModel, PathVoltagesAreTheVoltsOfTheMotionAlongThePath) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(-2.0, 2.0), speed_squared(0.01, 4.0);
  const JointChain chain = everyJointTypePair(rng)[2];  // a telescope on a pivot
  const PerJoint<DriveParams> params{drive(GravityModel::kCosine, 0.15, 0.3, 2.0, 0.05),
                                     drive(GravityModel::kSine, 0.2, 0.5, 4.0, 0.02)};
  const DriveModel feedforward(chain, params);
  const DriveModel rigid(params, ChainDynamics(chain, {LinkInertia{2.0, Point2(0.4, 0.0), 0.08},
                                                       LinkInertia{1.0, Point2(0.1, 0.05), 0.02}}));
  for (const DriveModel* drives : {&feedforward, &rigid}) {
    for (int i = 0; i < 100; ++i) {
      PathPoint p;
      p.q = draw(u, rng);
      p.dq_ds = draw(u, rng);
      p.d2q_ds2 = draw(u, rng);
      const double a = u(rng), b = speed_squared(rng), c = std::sqrt(b);
      const JointVector qdot = p.dq_ds * c;
      const JointVector volts = drives->volts(p.q, qdot, p.dq_ds * a + p.d2q_ds2 * b);
      const JointVector amps = drives->amps(volts, qdot);
      const PerJoint<PathVoltage> path = drives->pathVoltages(p);
      for (int j = 0; j < 2; ++j) {
        const PathVoltage& v = path[static_cast<size_t>(j)];
        const DriveParams& d = params[static_cast<size_t>(j)];
        const double coulomb = d.kS_volts * sgn(p.dq_ds[j]);
        const double from_path = v.alpha * a + v.beta * b + v.gamma * c + v.offset + coulomb;
        EXPECT_NEAR(from_path, volts[j], 1e-9 * (1.0 + std::abs(volts[j])));
        EXPECT_NEAR(from_path - d.gearing * p.dq_ds[j] / kv(d.motor) * c, amps[j] * resistance(d.motor),
                    1e-9 * (1.0 + std::abs(volts[j])));
      }
    }
  }
}

}  // namespace
}  // namespace cyber::planner

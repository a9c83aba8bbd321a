// ChainDynamics (docs/algorithm.md section 3, "Coupled rigid-body dynamics") against a numeric
// Lagrangian built only from linkFrames for every chain of one, two and three joints and for the
// shipped elevator-pivot-wrist, against the properties of M and c (M symmetric positive definite,
// qdot^T (Mdot - 2 C) qdot = 0), against hand-worked static cases, and against the independent
// referee's numbers for the two rigid-body reference robots.
#include "cyber/planner/chain.hpp"

#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "cyber/config/load_config.hpp"
#include "shipped_robots.hpp"

namespace cyber::planner {
namespace {

constexpr double kRpmToRadps = 2.0 * M_PI / 60.0;

// --- The numeric Lagrangian: L = T - V from the link frames alone, differentiated by central
// differences (fourth order), tau = d/dt dL/dqdot - dL/dq.

template <class F>
double derivative(F&& f, double h) {
  return (f(-2.0 * h) - 8.0 * f(-h) + 8.0 * f(h) - f(2.0 * h)) / (12.0 * h);
}

struct Model {
  JointChain chain;
  PerJoint<LinkInertia> bodies;  // one per link
  // Bodies fixed in a link besides its own (held pieces), each with its link's index: the
  // Lagrangian sums their energies separately, where ChainDynamics is given them combined.
  std::vector<std::pair<int, LinkInertia>> extra;
};

// T - V of one body fixed in link `link`.
double bodyLagrangian(const JointChain& chain, int link, const LinkInertia& body, const JointVector& q,
                      const JointVector& qdot) {
  constexpr double kStep = 1e-3;  // in time; qdot of order one
  const LinkFrame frame = linkFrames(chain, q)[link];
  const auto along = [&](double t) { return linkFrames(chain, q + t * qdot)[link]; };
  const Point2 velocity(derivative([&](double t) { return along(t).toWorld(body.cg_m).x(); }, kStep),
                        derivative([&](double t) { return along(t).toWorld(body.cg_m).y(); }, kStep));
  // omega = cos(phi) d sin(phi)/dt - sin(phi) d cos(phi)/dt: no angle wrap to unwrap.
  const double omega = frame.cos_angle * derivative([&](double t) { return along(t).sin_angle; }, kStep) -
                       frame.sin_angle * derivative([&](double t) { return along(t).cos_angle; }, kStep);
  const double kinetic = 0.5 * body.mass_kg * velocity.squaredNorm() + 0.5 * body.moi_kgm2 * omega * omega;
  return kinetic - body.mass_kg * kStandardGravityMps2 * frame.toWorld(body.cg_m).y();
}

double lagrangian(const Model& model, const JointVector& q, const JointVector& qdot) {
  double sum = 0.0;
  for (int i = 0; i < model.chain.size(); ++i) sum += bodyLagrangian(model.chain, i, model.bodies[i], q, qdot);
  for (const auto& [link, body] : model.extra) sum += bodyLagrangian(model.chain, link, body, q, qdot);
  return sum;
}

JointVector numericTorque(const Model& model, const JointVector& q, const JointVector& qdot, const JointVector& qddot) {
  constexpr double kStep = 1e-3;
  const int n = model.chain.size();
  JointVector tau(n);
  for (int j = 0; j < n; ++j) {
    const JointVector unit = JointVector::Unit(n, j);
    const auto momentum = [&](const JointVector& at_q, const JointVector& at_qdot) {
      return derivative([&](double e) { return lagrangian(model, at_q, at_qdot + e * unit); }, kStep);
    };
    // Along q(t) = q + qdot t + qddot t^2 / 2.
    const double momentum_rate =
        derivative([&](double t) { return momentum(q + qdot * t + 0.5 * qddot * t * t, qdot + qddot * t); }, kStep);
    const double force = derivative([&](double e) { return lagrangian(model, q + e * unit, qdot); }, kStep);
    tau[j] = momentum_rate - force;
  }
  return tau;
}

// The bodies ChainDynamics is given: each link's own with the extra bodies on it combined.
PerJoint<LinkInertia> combinedBodies(const Model& model) {
  PerJoint<LinkInertia> bodies = model.bodies;
  for (const auto& [link, body] : model.extra) bodies[link] = combine(bodies[link], body);
  return bodies;
}

// The joint types of a chain, first joint first.
using JointTypes = PerJoint<JointType>;

constexpr std::array<JointType, 2> kTypes = {JointType::kPrismatic, JointType::kRevolute};

// Every chain of `joint_count` joints: prismatic before revolute, the first joint varying slowest.
std::vector<JointTypes> everyChain(int joint_count) {
  std::vector<JointTypes> chains;
  for (int code = 0; code < (1 << joint_count); ++code) {
    JointTypes types;
    for (int j = 0; j < joint_count; ++j) {
      types.push_back(kTypes[static_cast<size_t>((code >> (joint_count - 1 - j)) & 1)]);
    }
    chains.push_back(types);
  }
  return chains;
}

// "prismatic-revolute-revolute" and so on.
std::string chainName(const JointTypes& types) {
  std::string name;
  for (const JointType type : types) {
    name += std::string(name.empty() ? "" : "-") + (type == JointType::kRevolute ? "revolute" : "prismatic");
  }
  return name;
}

// A chain of the given joint types with random origins, axes and bodies (cg off the link's x
// axis too), so no term is hidden by a zero.
Model randomModel(const JointTypes& types, std::mt19937& rng) {
  std::uniform_real_distribution<double> coordinate(-0.8, 0.8);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  std::uniform_real_distribution<double> mass(0.5, 6.0);
  std::uniform_real_distribution<double> moi(0.01, 0.4);
  constexpr std::array<const char*, kMaxJoints> kNames = {"a", "b", "c"};
  Model model;
  for (int j = 0; j < types.size(); ++j) {
    model.chain.push_back(
        ChainJoint{kNames[static_cast<size_t>(j)], types[j], Point2(coordinate(rng), coordinate(rng)), angle(rng), {}});
  }
  for (int j = 0; j < types.size(); ++j) {
    model.bodies.push_back(LinkInertia{mass(rng), Point2(coordinate(rng), coordinate(rng)), moi(rng)});
  }
  return model;
}

JointVector randomVector(int n, std::uniform_real_distribution<double>& values, std::mt19937& rng) {
  JointVector v(n);
  for (int j = 0; j < n; ++j) v[j] = values(rng);
  return v;
}

// torque, and its split into M qddot, c and g, against the numeric Lagrangian at one state.
void expectNumericTorque(const Model& model, const JointVector& q, const JointVector& qdot, const JointVector& qddot) {
  const ChainDynamics dynamics(model.chain, combinedBodies(model));
  const int n = model.chain.size();
  const JointVector expected = numericTorque(model, q, qdot, qddot);
  const JointVector actual = dynamics.torque(q, qdot, qddot);
  // Torques are of order 10-100 N m here (up to 420 N on the shipped elevator); the nested
  // differences agree to 5e-7 relative at worst over all these chains (their round-off is some
  // 1e-16 / (1e-3)^3 of L), a tenth of the bound.
  EXPECT_LT((actual - expected).norm(), 5e-6 * (1.0 + expected.norm()))
      << "q " << q.transpose() << " qdot " << qdot.transpose() << " qddot " << qddot.transpose() << "\nactual "
      << actual.transpose() << "\nnumeric " << expected.transpose();
  // The split itself: at rest only gravity remains (exactly: M 0 + c(q, 0) = 0), and c carries
  // all of the velocity.
  EXPECT_LT((dynamics.torque(q, JointVector::Zero(n), JointVector::Zero(n)) - dynamics.gravityTerms(q)).norm(), 1e-12);
  EXPECT_LT(
      (numericTorque(model, q, qdot, JointVector::Zero(n)) - dynamics.gravityTerms(q) - dynamics.velocityTerms(q, qdot))
          .norm(),
      5e-6 * (1.0 + expected.norm()));
}

// Every chain of `joint_count` joints, `trials` random models and states each.
void expectTorqueIsTheNumericLagrangians(int joint_count, unsigned seed, int trials) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> position(-2.0, 2.0);
  std::uniform_real_distribution<double> rate(-3.0, 3.0);
  for (const JointTypes& types : everyChain(joint_count)) {
    SCOPED_TRACE(chainName(types));
    for (int trial = 0; trial < trials; ++trial) {
      const Model model = randomModel(types, rng);
      const JointVector q = randomVector(joint_count, position, rng);
      const JointVector qdot = randomVector(joint_count, rate, rng);
      expectNumericTorque(model, q, qdot, randomVector(joint_count, rate, rng));
    }
  }
}

TEST(ChainDynamics, TorqueIsTheNumericLagrangiansForEveryJointTypePair) {
  expectTorqueIsTheNumericLagrangians(2, 2024, 20);
}

TEST(ChainDynamics, TorqueIsTheNumericLagrangiansForOneJointOfEitherType) {
  expectTorqueIsTheNumericLagrangians(1, 1, 20);
}

// Elevator + pivot + wrist, pivot + telescope + wrist, three pivots and the other five orders.
TEST(ChainDynamics, TorqueIsTheNumericLagrangiansForEveryChainOfThreeJoints) {
  expectTorqueIsTheNumericLagrangians(3, 3, 20);
}

// M(q) symmetric positive definite: v^T M v = sum_k m_k |J_k v|^2 + I_k (dphi_k/dq v)^2 is zero
// only when every body is still, and link k moves with joints 0..k, joint k's own column never
// zero (its travel, or its turn with I_k > 0), so by induction on k only for v = 0. The smallest
// eigenvalues seen are 0.066 (random chains) and 0.013 (the shipped robot).
void expectSymmetricPositiveDefinite(const JointMatrix& m) {
  EXPECT_LT((m - m.transpose()).norm(), 1e-12 * m.norm());
  const Eigen::SelfAdjointEigenSolver<JointMatrix> eigen(m);
  EXPECT_GT(eigen.eigenvalues().minCoeff(), 1e-6) << m;
}

// The energy identity qdot^T (Mdot - 2 C) qdot = 0 with C qdot = c(q, qdot): Mdot by central
// differences of M along q + t qdot.
void expectEnergyIdentity(const ChainDynamics& dynamics, const JointVector& q, const JointVector& qdot) {
  constexpr double kStep = 1e-3;
  const double power_of_mdot =
      derivative([&](double t) { return qdot.dot(dynamics.massMatrix(q + t * qdot) * qdot); }, kStep);
  const double power_of_c = qdot.dot(dynamics.velocityTerms(q, qdot));
  // Both sides are of order 2T |qdot| (2T = qdot^T M qdot); the scale below reaches 2 600 here.
  // Their difference's error is the truncation of the fourth-order difference, h^4 / 30 times a
  // fifth derivative of order |qdot|^5 times a side: 1.4e-11 of the scale at worst, against 1e-9.
  const double scale = 1.0 + qdot.dot(dynamics.massMatrix(q) * qdot) * (1.0 + qdot.norm());
  EXPECT_NEAR(power_of_mdot, 2.0 * power_of_c, 1e-9 * scale) << "q " << q.transpose() << " qdot " << qdot.transpose();
}

void expectMassMatrixAndEnergyIdentity(int joint_count, unsigned seed, int trials) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> position(-2.0, 2.0);
  std::uniform_real_distribution<double> rate(-3.0, 3.0);
  for (const JointTypes& types : everyChain(joint_count)) {
    SCOPED_TRACE(chainName(types));
    for (int trial = 0; trial < trials; ++trial) {
      const Model model = randomModel(types, rng);
      const ChainDynamics dynamics(model.chain, model.bodies);
      const JointVector q = randomVector(joint_count, position, rng);
      expectSymmetricPositiveDefinite(dynamics.massMatrix(q));
      expectEnergyIdentity(dynamics, q, randomVector(joint_count, rate, rng));
    }
  }
}

TEST(ChainDynamics, MassMatrixIsSymmetricPositiveDefiniteAndConservesEnergyForOneTwoAndThreeJoints) {
  for (int joint_count = 1; joint_count <= kMaxJoints; ++joint_count) {
    SCOPED_TRACE(joint_count);
    expectMassMatrixAndEnergyIdentity(joint_count, static_cast<unsigned>(7 + joint_count), 50);
  }
}

TEST(ChainDynamics, PathFormIsTheTorqueOfTheMotionAlongThePath) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> position(-2.0, 2.0);
  std::uniform_real_distribution<double> derivative_value(-2.0, 2.0);
  std::uniform_real_distribution<double> speed_squared(0.0, 4.0);
  for (const JointType first : kTypes) {
    for (const JointType second : kTypes) {
      SCOPED_TRACE(chainName({first, second}));
      for (int trial = 0; trial < 50; ++trial) {
        const Model model = randomModel({first, second}, rng);
        const ChainDynamics dynamics(model.chain, model.bodies);
        const JointVector q{{position(rng), position(rng)}};
        const JointVector dq_ds{{derivative_value(rng), derivative_value(rng)}};
        const JointVector d2q_ds2{{derivative_value(rng), derivative_value(rng)}};
        const double a = derivative_value(rng);
        const double b = speed_squared(rng);
        // eq. 11: qdot = q' sqrt(b), qddot = q'' b + q' a.
        const JointVector expected = dynamics.torque(q, dq_ds * std::sqrt(b), dq_ds * a + d2q_ds2 * b);
        const PathTorque path = dynamics.alongPath(q, dq_ds, d2q_ds2);
        EXPECT_LT((path.at(a, b) - expected).norm(), 1e-10 * (1.0 + expected.norm()));
      }
    }
  }
}

// A body as four equal point masses at +-r on its cg's x and y axes, r = sqrt(I / m): the same
// mass, cg and moment of inertia.
std::array<std::pair<double, Point2>, 4> pointMasses(const LinkInertia& body) {
  const double r = std::sqrt(body.moi_kgm2 / body.mass_kg);
  const double m = body.mass_kg / 4.0;
  return {{{m, body.cg_m + Point2(r, 0.0)},
           {m, body.cg_m - Point2(r, 0.0)},
           {m, body.cg_m + Point2(0.0, r)},
           {m, body.cg_m - Point2(0.0, r)}}};
}

TEST(ChainDynamics, CombinedBodyIsTheDirectSumOfItsPointMasses) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::uniform_real_distribution<double> mass(0.05, 5.0);
  std::uniform_real_distribution<double> moi(0.001, 0.5);
  for (int trial = 0; trial < 100; ++trial) {
    const LinkInertia link{mass(rng), Point2(coordinate(rng), coordinate(rng)), moi(rng)};
    const LinkInertia piece{mass(rng), Point2(coordinate(rng), coordinate(rng)), moi(rng)};
    double total = 0.0;
    Point2 moment = Point2::Zero();
    for (const LinkInertia& body : {link, piece}) {
      for (const auto& [m, p] : pointMasses(body)) {
        total += m;
        moment += m * p;
      }
    }
    const Point2 cg = moment / total;
    double inertia = 0.0;
    for (const LinkInertia& body : {link, piece}) {
      for (const auto& [m, p] : pointMasses(body)) inertia += m * (p - cg).squaredNorm();
    }
    const LinkInertia both = combine(link, piece);
    EXPECT_NEAR(both.mass_kg, total, 1e-12);
    EXPECT_LT((both.cg_m - cg).norm(), 1e-12);
    EXPECT_NEAR(both.moi_kgm2, inertia, 1e-12);
  }
}

TEST(ChainDynamics, CombiningWithNothingChangesNothing) {
  const LinkInertia link{2.0, Point2(0.3, -0.1), 0.05};
  const LinkInertia both = combine(link, LinkInertia{});
  EXPECT_DOUBLE_EQ(both.mass_kg, 2.0);
  EXPECT_LT((both.cg_m - link.cg_m).norm(), 1e-15);
  EXPECT_DOUBLE_EQ(both.moi_kgm2, 0.05);
  EXPECT_EQ(combine(LinkInertia{}, LinkInertia{}).mass_kg, 0.0);
}

TEST(ChainDynamics, StaticTorquesOfHandWorkedCases) {
  const double g = kStandardGravityMps2;
  // A horizontal arm (mass 2 kg, cg 0.4 m out) on a shoulder; the second link carries nothing.
  JointChain arm(2);
  arm[0] = ChainJoint{"shoulder", JointType::kRevolute, Point2(0.0, 0.5), 0.0, {}};
  arm[1] = ChainJoint{"elbow", JointType::kRevolute, Point2(0.7, 0.0), 0.0, {}};
  const ChainDynamics single(arm, {LinkInertia{2.0, Point2(0.4, 0.0), 0.1}, LinkInertia{}});
  EXPECT_NEAR(single.gravityTerms(JointVector{{0.0, 1.0}})[0], 2.0 * g * 0.4, 1e-12);
  EXPECT_NEAR(single.gravityTerms(JointVector{{M_PI / 2.0, 1.0}})[0], 0.0, 1e-12);
  EXPECT_NEAR(single.gravityTerms(JointVector{{M_PI / 3.0, 1.0}})[0], 2.0 * g * 0.4 * 0.5, 1e-12);
  // Spinning it needs no torque at constant rate: the centripetal force passes through the pivot.
  EXPECT_NEAR(single.velocityTerms(JointVector{{0.3, 1.0}}, (JointVector{{5.0, 0.0}}))[0], 0.0, 1e-12);
  // Its inertia about the pivot: I + m r^2.
  EXPECT_NEAR(single.massMatrix(JointVector{{0.3, 1.0}})(0, 0), 0.1 + 2.0 * 0.16, 1e-12);

  // A vertical elevator (carriage 5 kg) carrying a horizontal arm (1.5 kg, cg 0.3 m out).
  JointChain elevator(2);
  elevator[0] = ChainJoint{"lift", JointType::kPrismatic, Point2(0.1, 0.2), M_PI / 2.0, {}};
  elevator[1] = ChainJoint{"arm", JointType::kRevolute, Point2::Zero(), 0.0, {}};
  const ChainDynamics lift(elevator,
                           {LinkInertia{5.0, Point2(0.0, 0.1), 0.2}, LinkInertia{1.5, Point2(0.3, 0.0), 0.02}});
  const JointVector gravity = lift.gravityTerms(JointVector{{0.6, 0.0}});
  EXPECT_NEAR(gravity[0], 6.5 * g, 1e-12);
  EXPECT_NEAR(gravity[1], 1.5 * g * 0.3, 1e-12);
  // The carriage does not turn: its own moment of inertia never appears.
  EXPECT_NEAR(lift.massMatrix(JointVector{{0.6, 0.0}})(0, 0), 6.5, 1e-12);
}

// --- The referee: ../shared/tools/verify-trajectory's dynamics(), torque(), Drive.rigid_volts()
// and Drive.amps() run with python3 on the models ../shared/reference/<name>.json (numbers below
// copied from them) at the states below; its printed values are hard-coded here.

MotorParams motorFromReference(double stall_torque, double stall_current, double free_current, double free_rpm) {
  return MotorParams{12.0, stall_torque, stall_current, free_current, free_rpm * kRpmToRadps};
}

struct ReferenceCase {
  Model model{JointChain(2), PerJoint<LinkInertia>(2), {}};
  PerJoint<RigidBodyDrive> drives = PerJoint<RigidBodyDrive>(2);
  JointVector q, qdot, qddot;
  JointVector torque, volts, amps;  // the referee's
};

void expectReferee(const ReferenceCase& c) {
  const ChainDynamics dynamics(c.model.chain, c.model.bodies);
  const JointVector tau = dynamics.torque(c.q, c.qdot, c.qddot);
  for (int j = 0; j < 2; ++j) {
    SCOPED_TRACE(j);
    EXPECT_NEAR(tau[j], c.torque[j], 1e-9 * std::abs(c.torque[j]));
    const double volts = c.drives[j].volts(tau[j], c.qdot[j]);
    EXPECT_NEAR(volts, c.volts[j], 1e-9);
    EXPECT_NEAR(c.drives[j].amps(volts, c.qdot[j]), c.amps[j], 1e-9);
  }
}

TEST(ChainDynamics, MatchesTheRefereeOnTheDoubleJointedArmHoldingACone) {
  ReferenceCase c;
  // chargedup-2023-double-jointed.json: joints, drives.{shoulder,elbow} and pieces.cone.
  c.model.chain[0] = ChainJoint{"shoulder", JointType::kRevolute, Point2(0.0, 0.654), 0.0, {}};
  c.model.chain[1] = ChainJoint{"elbow", JointType::kRevolute, Point2(0.686, 0.0), 0.0, {}};
  const LinkInertia cone{0.652, Point2(0.99, 0.0), 0.0};
  c.model.bodies = {LinkInertia{1.036005, Point2(0.4318, 0.0), 0.08},
                    combine(LinkInertia{3.757559, Point2(0.769086, 0.0), 0.282261}, cone)};
  // The referee's bodies() for the elbow with the cone: (4.409559, 0.8017504746107265, 0,
  // 0.30937569508500357).
  EXPECT_NEAR(c.model.bodies[1].mass_kg, 4.409559, 1e-12);
  EXPECT_NEAR(c.model.bodies[1].cg_m.x(), 0.8017504746107265, 1e-12);
  EXPECT_NEAR(c.model.bodies[1].moi_kgm2, 0.30937569508500357, 1e-12);
  const MotorParams neo = motorFromReference(2.6, 105.0, 1.8, 5676.0);
  c.drives = {RigidBodyDrive{neo, 2, 197.0, 0.0, 10.0, 30.0}, RigidBodyDrive{neo, 1, 200.0, 0.0, 10.0, 30.0}};
  c.q = JointVector{{1.2, 3.9}};
  c.qdot = JointVector{{0.7, -1.3}};
  c.qddot = JointVector{{2.0, -3.0}};
  c.torque = JointVector{{25.018709709967677, 5.6221911244124856}};
  c.volts = JointVector{{3.0293810532543155, -5.02935762085104}};
  c.amps = JointVector{{2.5643933224781379, 1.1352501308909824}};
  expectReferee(c);
}

TEST(ChainDynamics, MatchesTheRefereeOnThePivotTelescopeHoldingABall) {
  ReferenceCase c;
  // pivot-telescope.json: joints, drives.{pivot,telescope} and pieces.ball.
  c.model.chain[0] = ChainJoint{"pivot", JointType::kRevolute, Point2(-0.15, 0.32), 0.0, {}};
  c.model.chain[1] = ChainJoint{"telescope", JointType::kPrismatic, Point2::Zero(), 0.0, {}};
  const LinkInertia ball{0.25, Point2(0.68, 0.0), 0.0};
  c.model.bodies = {LinkInertia{3.5, Point2(0.22, 0.0), 0.15}, combine(LinkInertia{3.0, Point2(0.4, 0.0), 0.12}, ball)};
  const MotorParams kraken = motorFromReference(7.09, 366.0, 2.0, 6000.0);
  c.drives = {RigidBodyDrive{kraken, 2, 80.0, 0.15, 12.0, 60.0}, RigidBodyDrive{kraken, 1, 350.0, 0.2, 12.0, 40.0}};
  c.q = JointVector{{0.8, 0.5}};
  c.qdot = JointVector{{-0.9, 0.6}};
  c.qddot = JointVector{{1.5, -2.0}};
  c.torque = JointVector{{27.315481074840964, 13.937345353664366}};
  c.volts = JointVector{{-1.2286337206116487, 4.2561861504419713}};
  c.amps = JointVector{{4.2379990068686455, 8.1556390890353292}};
  expectReferee(c);
}

// The referee's closed forms for the two pairs no reference robot has, on made-up chains (cg off
// the link axis): ../shared/tools/verify-trajectory's torque() called with python3 on these joints
// and bodies, at q (0.4, 0.7), qdot (0.5, -1.1), qddot (1.3, 0.4).
TEST(ChainDynamics, MatchesTheRefereesClosedFormsForAnElevatorPairAndTwoSlides) {
  const JointVector q{{0.4, 0.7}}, qdot{{0.5, -1.1}}, qddot{{1.3, 0.4}};
  const double deg = M_PI / 180.0;
  JointChain elevator_arm(2);
  elevator_arm[0] = ChainJoint{"lift", JointType::kPrismatic, Point2(0.1, 0.2), 80.0 * deg, {}};
  elevator_arm[1] = ChainJoint{"arm", JointType::kRevolute, Point2(0.05, 0.3), 10.0 * deg, {}};
  const ChainDynamics pr(elevator_arm,
                         {LinkInertia{5.0, Point2(0.0, 0.1), 0.2}, LinkInertia{1.5, Point2(0.3, 0.05), 0.02}});
  const JointVector pr_tau = pr.torque(q, qdot, qddot);
  EXPECT_NEAR(pr_tau[0], 70.77123530340684, 1e-9);
  EXPECT_NEAR(pr_tau[1], 2.5365136106389561, 1e-9);

  JointChain slides(2);
  slides[0] = ChainJoint{"up", JointType::kPrismatic, Point2(0.0, 0.1), 90.0 * deg, {}};
  slides[1] = ChainJoint{"out", JointType::kPrismatic, Point2(0.1, 0.0), 30.0 * deg, {}};
  const ChainDynamics pp(slides, {LinkInertia{4.0, Point2(0.1, 0.1), 0.1}, LinkInertia{2.0, Point2(0.2, -0.1), 0.05}});
  const JointVector pp_tau = pp.torque(q, qdot, qddot);
  EXPECT_NEAR(pp_tau[0], 67.039900000000003, 1e-9);
  EXPECT_NEAR(pp_tau[1], 11.906649999999997, 1e-9);
}

TEST(ChainDynamics, PathVoltageIsTheDriveVoltageAlongThePath) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> value(-2.0, 2.0);
  std::uniform_real_distribution<double> speed_squared(0.01, 4.0);
  const Model model = randomModel({JointType::kRevolute, JointType::kPrismatic}, rng);
  const ChainDynamics dynamics(model.chain, model.bodies);
  const MotorParams kraken = motorFromReference(7.09, 366.0, 2.0, 6000.0);
  const PerJoint<RigidBodyDrive> drives = {RigidBodyDrive{kraken, 2, 80.0, 0.15, 12.0, 60.0},
                                           RigidBodyDrive{kraken, 1, 350.0, 0.2, 12.0, 40.0}};
  for (int trial = 0; trial < 50; ++trial) {
    const JointVector q{{value(rng), value(rng)}};
    const JointVector dq_ds{{value(rng), value(rng)}};
    const JointVector d2q_ds2{{value(rng), value(rng)}};
    const double a = value(rng);
    const double b = speed_squared(rng);
    const JointVector qdot = dq_ds * std::sqrt(b);
    const JointVector tau = dynamics.torque(q, qdot, dq_ds * a + d2q_ds2 * b);
    const PathTorque path = dynamics.alongPath(q, dq_ds, d2q_ds2);
    for (int j = 0; j < 2; ++j) {
      const PathVoltage v = pathVoltage(drives[j], path, dq_ds, j);
      const double coulomb = drives[j].kS_volts * (dq_ds[j] > 0.0 ? 1.0 : -1.0);
      const double volts = v.alpha * a + v.beta * b + v.gamma * std::sqrt(b) + v.offset + coulomb;
      EXPECT_NEAR(volts, drives[j].volts(tau[j], qdot[j]), 1e-9);
      // Current times R: the same row without the back-EMF.
      EXPECT_NEAR(v.alpha * a + v.beta * b + v.offset + coulomb,
                  drives[j].amps(volts, qdot[j]) * drives[j].motor.resistanceOhms(), 1e-9);
    }
  }
}

// --- The three-joint shipped robot: config/reefscape-2025-elevator-pivot-wrist.toml as loaded.

constexpr const char* kElevatorPivotWrist = "reefscape-2025-elevator-pivot-wrist";

// The robot's chain and link bodies, the pieces of `held` as extra bodies on their links.
Model shippedModel(const RobotModel& robot, HeldPieces held) {
  Model model{robot.joints, robot.bodies, {}};
  for (size_t i = 0; i < robot.pieces.size(); ++i) {
    if (held.holds(static_cast<int>(i))) model.extra.emplace_back(robot.pieces[i].joint, robot.piece_inertias[i]);
  }
  return model;
}

// A state within the joint ranges, at rates and accelerations of the robot's moves (up to
// 4 m/s or rad/s and 20 m/s^2 or rad/s^2).
struct State {
  JointVector q, qdot, qddot;
};
State randomState(const RobotModel& robot, std::mt19937& rng) {
  std::uniform_real_distribution<double> rate(-4.0, 4.0);
  std::uniform_real_distribution<double> acceleration(-20.0, 20.0);
  const int n = robot.jointCount();
  State s{JointVector(n), randomVector(n, rate, rng), randomVector(n, acceleration, rng)};
  for (int j = 0; j < n; ++j) {
    s.q[j] = std::uniform_real_distribution<double>(robot.range(j).min, robot.range(j).max)(rng);
  }
  return s;
}

TEST(ChainDynamics, ShippedElevatorPivotWristIsTheNumericLagrangiansAtRandomStates) {
  const config::Config config =
      config::loadConfigFile(test::sourceFile(std::string("config/") + kElevatorPivotWrist + ".toml"));
  const RobotModel& robot = config.robot;
  ASSERT_EQ(robot.jointCount(), 3);
  ASSERT_EQ(robot.drive_kind, DriveKind::kRigidBody);
  ASSERT_EQ(robot.piece_inertias.size(), robot.pieces.size());  // coral and algae, each with its mass
  std::mt19937 rng(34);
  for (int set = 0; set < robot.pieceSetCount(); ++set) {
    const HeldPieces held = HeldPieces::fromIndex(set);
    SCOPED_TRACE(robot.pieceSetName(held));
    const Model model = shippedModel(robot, held);
    const ChainDynamics dynamics(model.chain, combinedBodies(model));
    double lifted_kg = 0.0;
    for (const LinkInertia& body : model.bodies) lifted_kg += body.mass_kg;
    for (const auto& [link, piece] : model.extra) lifted_kg += piece.mass_kg;
    for (int trial = 0; trial < 25; ++trial) {
      const State s = randomState(robot, rng);
      expectNumericTorque(model, s.q, s.qdot, s.qddot);
      expectSymmetricPositiveDefinite(dynamics.massMatrix(s.q));
      expectEnergyIdentity(dynamics, s.q, s.qdot);
      // The carriage slides straight up without turning: the elevator holds up and accelerates
      // everything it lifts, whatever the arm's pose (to round-off: sin 90 deg, cos 90 deg).
      EXPECT_NEAR(dynamics.gravityTerms(s.q)[0], lifted_kg * kStandardGravityMps2, 1e-9);
      EXPECT_NEAR(dynamics.massMatrix(s.q)(0, 0), lifted_kg, 1e-12);
    }
  }
}

}  // namespace
}  // namespace cyber::planner

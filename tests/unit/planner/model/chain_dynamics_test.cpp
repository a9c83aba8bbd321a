// ChainDynamics (docs/algorithm.md section 3, "Coupled rigid-body dynamics") against a numeric
// Lagrangian built only from linkFrames, against hand-worked static cases, and against the
// independent referee's numbers for the two rigid-body reference robots.
#include "cyber/planner/chain.hpp"

#include <cmath>
#include <random>

#include <Eigen/Dense>
#include <gtest/gtest.h>

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
  JointChain chain = JointChain(2);
  PerJoint<LinkInertia> bodies = PerJoint<LinkInertia>(2);
};

double lagrangian(const Model& model, const JointVector& q, const JointVector& qdot) {
  constexpr double kStep = 1e-3;  // in time; qdot of order one
  double kinetic = 0.0;
  double potential = 0.0;
  const auto frames = linkFrames(model.chain, q);
  for (int i = 0; i < 2; ++i) {
    const LinkInertia& body = model.bodies[i];
    const auto along = [&](double t) { return linkFrames(model.chain, q + t * qdot)[i]; };
    const Point2 velocity(derivative([&](double t) { return along(t).toWorld(body.cg_m).x(); }, kStep),
                          derivative([&](double t) { return along(t).toWorld(body.cg_m).y(); }, kStep));
    // omega = cos(phi) d sin(phi)/dt - sin(phi) d cos(phi)/dt: no angle wrap to unwrap.
    const double omega = frames[i].cos_angle * derivative([&](double t) { return along(t).sin_angle; }, kStep) -
                         frames[i].sin_angle * derivative([&](double t) { return along(t).cos_angle; }, kStep);
    kinetic += 0.5 * body.mass_kg * velocity.squaredNorm() + 0.5 * body.moi_kgm2 * omega * omega;
    potential += body.mass_kg * kStandardGravityMps2 * frames[i].toWorld(body.cg_m).y();
  }
  return kinetic - potential;
}

JointVector numericTorque(const Model& model, const JointVector& q, const JointVector& qdot, const JointVector& qddot) {
  constexpr double kStep = 1e-3;
  JointVector tau(2);
  for (int j = 0; j < 2; ++j) {
    const JointVector unit = JointVector::Unit(2, j);
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

const char* pairName(JointType first, JointType second) {
  if (first == JointType::kRevolute) return second == JointType::kRevolute ? "revolute-revolute" : "revolute-prismatic";
  return second == JointType::kRevolute ? "prismatic-revolute" : "prismatic-prismatic";
}

// A chain of the given joint types with random origins, axes and bodies (cg off the link's x
// axis too), so no term is hidden by a zero.
Model randomModel(JointType first, JointType second, std::mt19937& rng) {
  std::uniform_real_distribution<double> coordinate(-0.8, 0.8);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  std::uniform_real_distribution<double> mass(0.5, 6.0);
  std::uniform_real_distribution<double> moi(0.01, 0.4);
  Model model;
  model.chain[0] = ChainJoint{"a", first, Point2(coordinate(rng), coordinate(rng)), angle(rng), {}};
  model.chain[1] = ChainJoint{"b", second, Point2(coordinate(rng), coordinate(rng)), angle(rng), {}};
  for (LinkInertia& body : model.bodies) {
    body = LinkInertia{mass(rng), Point2(coordinate(rng), coordinate(rng)), moi(rng)};
  }
  return model;
}

constexpr std::array<JointType, 2> kTypes = {JointType::kPrismatic, JointType::kRevolute};

TEST(ChainDynamics, TorqueIsTheNumericLagrangiansForEveryJointTypePair) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> position(-2.0, 2.0);
  std::uniform_real_distribution<double> rate(-3.0, 3.0);
  for (const JointType first : kTypes) {
    for (const JointType second : kTypes) {
      SCOPED_TRACE(pairName(first, second));
      for (int trial = 0; trial < 20; ++trial) {
        const Model model = randomModel(first, second, rng);
        const ChainDynamics dynamics(model.chain, model.bodies);
        const JointVector q{{position(rng), position(rng)}};
        const JointVector qdot{{rate(rng), rate(rng)}};
        const JointVector qddot{{rate(rng), rate(rng)}};
        const JointVector expected = numericTorque(model, q, qdot, qddot);
        const JointVector actual = dynamics.torque(q, qdot, qddot);
        // Torques are of order 10-100 N m here; the nested differences agree to 2.5e-7 relative.
        EXPECT_LT((actual - expected).norm(), 5e-6 * (1.0 + expected.norm()))
            << "q " << q.transpose() << " qdot " << qdot.transpose() << " qddot " << qddot.transpose() << "\nactual "
            << actual.transpose() << "\nnumeric " << expected.transpose();
        // The split itself: at rest only gravity remains, and c carries all of the velocity.
        EXPECT_LT((dynamics.torque(q, JointVector::Zero(2), JointVector::Zero(2)) - dynamics.gravityTerms(q)).norm(),
                  1e-12);
        EXPECT_LT((numericTorque(model, q, qdot, JointVector::Zero(2)) - dynamics.gravityTerms(q) -
                   dynamics.velocityTerms(q, qdot))
                      .norm(),
                  5e-6 * (1.0 + expected.norm()));
      }
    }
  }
}

TEST(ChainDynamics, MassMatrixIsSymmetricPositiveDefiniteForEveryJointTypePair) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> position(-2.0, 2.0);
  for (const JointType first : kTypes) {
    for (const JointType second : kTypes) {
      SCOPED_TRACE(pairName(first, second));
      for (int trial = 0; trial < 50; ++trial) {
        const Model model = randomModel(first, second, rng);
        const ChainDynamics dynamics(model.chain, model.bodies);
        const Eigen::Matrix2d m = dynamics.massMatrix(JointVector{{position(rng), position(rng)}});
        EXPECT_LT(std::abs(m(0, 1) - m(1, 0)), 1e-12 * m.norm());
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(m);
        EXPECT_GT(eigen.eigenvalues().minCoeff(), 1e-6) << m;
      }
    }
  }
}

TEST(ChainDynamics, PathFormIsTheTorqueOfTheMotionAlongThePath) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> position(-2.0, 2.0);
  std::uniform_real_distribution<double> derivative_value(-2.0, 2.0);
  std::uniform_real_distribution<double> speed_squared(0.0, 4.0);
  for (const JointType first : kTypes) {
    for (const JointType second : kTypes) {
      SCOPED_TRACE(pairName(first, second));
      for (int trial = 0; trial < 50; ++trial) {
        const Model model = randomModel(first, second, rng);
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
  Model model;
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
  const Model model = randomModel(JointType::kRevolute, JointType::kPrismatic, rng);
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

}  // namespace
}  // namespace cyber::planner

// linkFrames against the chain rule written as 3x3 homogeneous matrices (docs/algorithm.md
// section 1): link k = parent * Trans(origin) * J(q_k).
#include "cyber/planner/chain.hpp"

#include <random>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace cyber::planner {
namespace {

Eigen::Matrix3d translation(const Point2& p) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
  m.block<2, 1>(0, 2) = p;
  return m;
}

Eigen::Matrix3d rotation(double angle) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
  m.block<2, 2>(0, 0) << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return m;
}

Eigen::Matrix3d jointMatrix(const ChainJoint& joint, double q) {
  const Eigen::Matrix3d move = joint.type == JointType::kRevolute
                                   ? rotation(joint.axis_rad + q)
                                   : translation(q * Point2(std::cos(joint.axis_rad), std::sin(joint.axis_rad)));
  return translation(joint.origin_m) * move;
}

TEST(JointChain, LinkFramesAreTheProductOfTheJointTransformsForEveryJointTypePair) {
  std::mt19937 rng(24);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  int checked = 0;
  for (const JointType first : {JointType::kPrismatic, JointType::kRevolute}) {
    for (const JointType second : {JointType::kPrismatic, JointType::kRevolute}) {
      for (int trial = 0; trial < 200; ++trial) {
        JointChain chain(2);
        chain[0] = ChainJoint{"a", first, Point2(u(rng), u(rng)), u(rng), {}};
        chain[1] = ChainJoint{"b", second, Point2(u(rng), u(rng)), u(rng), {}};
        const JointVector q{{u(rng), u(rng)}};
        const auto frames = linkFrames(chain, q);
        const Eigen::Matrix3d m0 = jointMatrix(chain[0], q[0]);
        const Eigen::Matrix3d m1 = m0 * jointMatrix(chain[1], q[1]);
        const Point2 p(u(rng), u(rng));
        const Eigen::Vector3d h(p.x(), p.y(), 1.0);
        EXPECT_LT((frames[0].toWorld(p) - (m0 * h).head<2>()).norm(), 1e-12);
        EXPECT_LT((frames[1].toWorld(p) - (m1 * h).head<2>()).norm(), 1e-12);
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 800);
}

TEST(JointChain, PointJacobianMatchesCentralDifferencesForEveryJointTypePair) {
  std::mt19937 rng(25);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (const JointType first : {JointType::kPrismatic, JointType::kRevolute}) {
    for (const JointType second : {JointType::kPrismatic, JointType::kRevolute}) {
      for (int trial = 0; trial < 50; ++trial) {
        JointChain chain(2);
        chain[0] = ChainJoint{"a", first, Point2(u(rng), u(rng)), u(rng), {}};
        chain[1] = ChainJoint{"b", second, Point2(u(rng), u(rng)), u(rng), {}};
        // Every slot of its capacity set: g++ 12 at -O3 (the arm64 build) cannot bound the chain's
        // size where chainPose is inlined here and calls the unused third slot uninitialised.
        JointVector q = JointVector::Zero(kMaxJoints);
        q.conservativeResize(2);
        q[0] = u(rng);
        q[1] = u(rng);
        const Point2 p(u(rng), u(rng));
        const ChainPose pose = chainPose(chain, q);
        for (int link = 0; link < 2; ++link) {
          const Eigen::Matrix2d jacobian = pose.pointJacobian(link, pose.frames[static_cast<size_t>(link)].toWorld(p));
          constexpr double h = 1e-6;
          for (int j = 0; j < 2; ++j) {
            JointVector dq = JointVector::Zero(2);
            dq[j] = h;
            const Point2 diff = (linkFrames(chain, q + dq)[static_cast<size_t>(link)].toWorld(p) -
                                 linkFrames(chain, q - dq)[static_cast<size_t>(link)].toWorld(p)) /
                                (2 * h);
            EXPECT_LT((diff - jacobian.col(j)).norm(), 1e-8) << "link " << link << " joint " << j;
          }
        }
      }
    }
  }
}

TEST(JointChain, AnElevatorKeepsTheWorldsOrientationAndItsArmAngleIsMeasuredFromX) {
  JointChain chain(2);
  chain[0] = ChainJoint{"lift", JointType::kPrismatic, Point2(-0.4, 0.2), 80.0 * M_PI / 180.0, {0.0, 2.0}};
  chain[1] = ChainJoint{"pivot", JointType::kRevolute, Point2::Zero(), 0.0, {0.0, 6.0}};
  const auto frames = linkFrames(chain, JointVector{{1.0, 0.5}});
  EXPECT_NEAR(frames[0].angle_rad(), 0.0, 1e-12);
  EXPECT_NEAR(frames[1].angle_rad(), 0.5, 1e-12);
  EXPECT_NEAR(frames[1].origin_m.x(), -0.4 + std::cos(80.0 * M_PI / 180.0), 1e-12);
  EXPECT_NEAR(frames[1].origin_m.y(), 0.2 + std::sin(80.0 * M_PI / 180.0), 1e-12);
}

}  // namespace
}  // namespace cyber::planner

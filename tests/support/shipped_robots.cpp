#include "shipped_robots.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/trajectory.hpp"

namespace cyber::test {

using planner::JointVector;

std::string shippedRobotParamName(const ::testing::TestParamInfo<const char*>& info) {
  std::string name = info.param;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

std::string sourceFile(const std::string& relative) { return std::string(CYBER_SOURCE_DIR) + "/" + relative; }

const ShippedRobot& shippedRobot(const std::string& name) {
  static std::map<std::string, std::unique_ptr<ShippedRobot>> cache;
  auto& slot = cache[name];
  if (!slot) {
    config::Config config = config::loadConfigFile(sourceFile("config/" + name + ".toml"));
    auto planner = planner::MotionPlanner::create(config.robot);
    if (!planner.ok()) {
      ADD_FAILURE() << name << ": " << planner.error().message;
      std::abort();
    }
    slot = std::make_unique<ShippedRobot>(ShippedRobot{std::move(config), std::move(planner).value()});
  }
  return *slot;
}

std::vector<NamedMove> namedMoves(const config::Config& config) {
  std::vector<NamedMove> out;
  for (const config::PoseSet& set : config.poses) {
    for (const config::NamedPose& from : set.poses) {
      for (const config::NamedPose& to : set.poses) {
        if (from.name == to.name) continue;
        NamedMove move{set.name + ":" + from.name + "->" + to.name, {}};
        move.request.start = from.q;
        move.request.goal = to.q;
        move.request.pieces = set.pieces;
        out.push_back(std::move(move));
      }
    }
  }
  return out;
}

JointVector namedPose(const config::Config& config, const std::string& set, const std::string& name) {
  for (const config::PoseSet& poses : config.poses) {
    if (poses.name != set) continue;
    for (const config::NamedPose& pose : poses.poses) {
      if (pose.name == name) return pose.q;
    }
  }
  ADD_FAILURE() << "no pose " << set << ":" << name;
  return JointVector::Zero(config.robot.jointCount());
}

void expectSound(const planner::RobotModel& model, const planner::Trajectory& trajectory, planner::HeldPieces pieces,
                 double offset_m, const std::string& label, double columns_step_s) {
  const planner::CollisionWorld world(model, model.scenes.front(), pieces, offset_m);
  const int samples = static_cast<int>(std::floor(trajectory.duration_s() / 0.001));
  for (int i = 0; i <= samples + 1; ++i) {
    const double t = std::min(i * 0.001, trajectory.duration_s());
    const JointVector q = trajectory.sampleMotion(t).q;
    ASSERT_TRUE(model.withinLimits(q, 1e-9)) << label << " at t = " << t << ": " << q.transpose();
    const double d = world.distance(q).value;
    ASSERT_GE(d, model.clearance_m - 1e-6) << label << " at t = " << t;
  }
  EXPECT_TRUE(planner::withinDriveLimits(trajectory, model.planner.topp)) << label;
  const planner::ColumnConsistency columns = planner::columnConsistency(trajectory, columns_step_s);
  EXPECT_LE(columns.position_error, 0.01) << label;
  EXPECT_LE(columns.velocity_error, 0.02) << label;
}

double expectNearTheFastestRide(const planner::Trajectory& trajectory, const std::string& label) {
  const std::optional<double> ride = planner::fastestRideAlongPath(trajectory, kRideStepS);
  EXPECT_TRUE(ride) << label << ": no ride along its path";
  if (!ride) return 0.0;
  const double ratio = trajectory.duration_s() / *ride;
  EXPECT_LE(ratio, 1.02) << label;
  return ratio;
}

}  // namespace cyber::test

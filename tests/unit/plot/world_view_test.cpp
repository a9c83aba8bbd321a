// The world view of the reference robot at the public poses: pixels just inside each reef
// obstacle's vertices, and just inside the arm's tip corners and the held coral's end, have the
// obstacle, arm and coral colours, and pixels just outside do not. The APNG animation is a
// well-formed PNG whose frames, sequence numbers and CRCs agree.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include "cyber/config/load_config.hpp"
#include "cyber/planner.hpp"
#include "cyber/plot/world_view.hpp"
#include "pixel_checks.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"

namespace cyber::plot {
namespace {

using pixels::centroid;
using pixels::corner;
using pixels::Image;
using pixels::inset;
using pixels::near;
using pixels::tempPath;
using planner::Point2;

class WorldView : public ::testing::Test {
 protected:
  config::Config config_ = config::loadEmbeddedDefaultConfig();
  const planner::RobotModel& robot_ = config_.robot;
};

TEST_F(WorldView, ReefObstacleVerticesAreWhereTheConfigPutsThem) {
  const std::string path = tempPath("world_stow");
  const planner::JointVector stow = test::publicPoses("none").front().q;
  const auto written = renderWorldPng(robot_, 0, {}, stow, "STOW", path);
  ASSERT_TRUE(written.ok()) << written.error().message;
  const Image image(path);
  ASSERT_TRUE(image.ok());
  const WorldCanvas c = worldPngCanvas(robot_);
  int checked = 0;
  std::vector<planner::NamedPolygon> drawn = robot_.scenes[0].obstacles;
  drawn.insert(drawn.end(), robot_.scenes[0].fixed.begin(), robot_.scenes[0].fixed.end());
  for (const auto& o : drawn) {
    const auto& vertices = o.polygon.vertices();
    for (size_t i = 0; i < vertices.size(); ++i) {
      const Point2& v = vertices[i];
      if (v.x() < c.x0 || v.x() > c.x1 || v.y() < c.y0 || v.y() > c.y1) continue;  // the floor's far corners
      const Point2 in = corner(c, vertices, i, 2.5);
      const auto got = image.at(in.x(), in.y());
      EXPECT_TRUE(near(got, kWorldColors.obstacle))
          << o.name << " vertex " << v.transpose() << " got " << got[0] << "," << got[1] << "," << got[2];
      ++checked;
    }
  }
  EXPECT_GE(checked, 25);
  // Just outside the l4_post's top-left corner and the trough's top-right corner: sky.
  for (const Point2& v : {Point2(0.03, 1.81), Point2(0.248, 0.514)}) {
    const Point2 out = inset(c, v, v + Point2(-1, 1), 3.0);
    EXPECT_TRUE(near(image.at(out.x(), out.y()), kWorldColors.sky)) << v.transpose();
  }
  std::filesystem::remove(path);
}

// At every public pose of the coral set, the arm's tip corners and the coral's far end are drawn
// where planner::linkFrames puts them.
TEST_F(WorldView, ArmTipAndHeldCoralAreWhereTheGeometryPutsThem) {
  const WorldCanvas c = worldPngCanvas(robot_);
  const planner::ConvexPolygon& arm = robot_.links.front().polygons.front();
  const int coral_index = robot_.pieceIndex("coral");
  const planner::ConvexPolygon& coral = robot_.pieces[static_cast<size_t>(coral_index)].polygons.front();
  const auto& arm_color = kWorldColors.links[1];
  const auto& coral_color = kWorldColors.pieces[coral_index];
  const Point2 coral_mid = centroid(coral.vertices());
  for (const auto& pose : test::publicPoses("coral")) {
    const std::string path = tempPath("world_" + pose.name);
    const auto written = renderWorldPng(robot_, 0, test::referencePieces("coral"), pose.q, pose.name, path);
    ASSERT_TRUE(written.ok()) << written.error().message;
    const Image image(path);
    ASSERT_TRUE(image.ok());
    const planner::LinkFrame p = planner::linkFrames(robot_.joints, pose.q)[1];
    // The arm's tip corners: (0.25, +-0.1) in the arm frame; the coral covers the tip's middle.
    std::vector<Point2> arm_world;
    for (const Point2& v : arm.vertices()) arm_world.push_back(p.toWorld(v));
    for (size_t i = 0; i < arm_world.size(); ++i) {
      if (arm.vertices()[i].x() < 0.2) continue;
      const Point2 in = corner(c, arm_world, i, 2.5);
      EXPECT_TRUE(near(image.at(in.x(), in.y()), arm_color))
          << pose.name << " arm corner " << arm.vertices()[i].transpose();
      const Point2 out = corner(c, arm_world, i, -4.0);
      EXPECT_FALSE(near(image.at(out.x(), out.y()), arm_color))
          << pose.name << " arm corner " << arm.vertices()[i].transpose();
    }
    const Point2 end = p.toWorld(Point2(coral.vertices()[1].x(), 0.0));  // middle of the coral's far end
    const Point2 in = inset(c, end, p.toWorld(coral_mid), 3.0);
    EXPECT_TRUE(near(image.at(in.x(), in.y()), coral_color)) << pose.name;
    const Point2 out = inset(c, end, p.toWorld(coral_mid), -4.0);
    EXPECT_FALSE(near(image.at(out.x(), out.y()), coral_color)) << pose.name;
    EXPECT_FALSE(near(image.at(out.x(), out.y()), arm_color)) << pose.name;
    std::filesystem::remove(path);
  }
}

uint32_t be32(const std::vector<uint8_t>& b, size_t at) {
  return (uint32_t{b[at]} << 24) | (uint32_t{b[at + 1]} << 16) | (uint32_t{b[at + 2]} << 8) | uint32_t{b[at + 3]};
}

TEST_F(WorldView, AnimationIsAWellFormedApng) {
  Move move;
  for (int k = 0; k <= 50; ++k) {
    const double s = k / 50.0;
    move.time_s.push_back(s);
    move.q.push_back(planner::JointVector{{0.20 + s * (0.58 - 0.20), 1.57 + s * (2.97 - 1.57)}});  // STOW -> INTAKE
  }
  const std::string path = tempPath("anim");
  const auto written = renderAnimationApng(robot_, 0, {}, move, 10, "STOW -> INTAKE", path);
  ASSERT_TRUE(written.ok()) << written.error().message;
  std::ifstream in(path, std::ios::binary);
  const std::vector<uint8_t> b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(b.size(), 8u);
  std::map<std::string, int> count;
  std::vector<uint32_t> sequence;
  uint32_t frames = 0;
  size_t at = 8;
  while (at + 12 <= b.size()) {
    const uint32_t length = be32(b, at);
    ASSERT_LE(at + 12 + length, b.size());
    const std::string type(b.begin() + static_cast<long>(at + 4), b.begin() + static_cast<long>(at + 8));
    EXPECT_EQ(be32(b, at + 8 + length), static_cast<uint32_t>(crc32(0L, &b[at + 4], 4 + length))) << type;
    if (type == "acTL") frames = be32(b, at + 8);
    if (type == "fcTL" || type == "fdAT") sequence.push_back(be32(b, at + 8));
    ++count[type];
    at += 12 + length;
  }
  EXPECT_EQ(at, b.size());
  // 1 s at 10 frames/s: 11 frames, one of them moved onto the smallest clearance.
  EXPECT_EQ(frames, 11u);
  EXPECT_EQ(count["fcTL"], 11);
  EXPECT_EQ(count["IHDR"], 1);
  EXPECT_GE(count["IDAT"], 1);
  EXPECT_GE(count["fdAT"], 10);
  for (size_t i = 0; i < sequence.size(); ++i) EXPECT_EQ(sequence[i], i);
  // A decoder without APNG support shows the first frame: cairo reads it.
  const Image first(path);
  EXPECT_TRUE(first.ok());
  std::filesystem::remove(path);
}

TEST_F(WorldView, PicturesThatCannotBeMadeSayWhyWithTheirPath) {
  const auto empty = renderFilmstripPng(robot_, 0, {}, Move{}, 4, "empty", "/tmp/empty.png");
  ASSERT_EQ(empty.status(), PlotStatus::kNothingToDraw);
  EXPECT_EQ(empty.error().message, "/tmp/empty.png: the move has no samples");
  EXPECT_EQ(renderAnimationApng(robot_, 0, {}, Move{}, 10, "empty", "/tmp/empty.png").status(),
            PlotStatus::kNothingToDraw);
  const planner::JointVector stow = test::publicPoses("none").front().q;
  const auto unwritable = renderWorldPng(robot_, 0, {}, stow, "STOW", "/nonexistent/world.png");
  ASSERT_EQ(unwritable.status(), PlotStatus::kCannotWrite);
  EXPECT_EQ(unwritable.error().message.rfind("/nonexistent/world.png: ", 0), 0u) << unwritable.error().message;
}

TEST_F(WorldView, SmallestClearanceIsTheMinimumOverTheSamples) {
  Move move;
  for (int k = 0; k <= 20; ++k) {
    move.time_s.push_back(k * 0.05);
    move.q.push_back(planner::JointVector{{1.22, 5.69 - 0.02 * std::abs(k - 12)}});  // L3, swinging closest at k = 12
  }
  const Clearance smallest = smallestClearance(robot_, 0, {}, move);
  const planner::CollisionWorld world(robot_, robot_.scenes[0], {});
  double brute = 1e9;
  size_t arg = 0;
  for (size_t k = 0; k < move.q.size(); ++k) {
    const double d = world.distance(move.q[k]).value;
    if (d < brute) brute = d, arg = k;
  }
  EXPECT_EQ(smallest.distance_m, brute);
  EXPECT_EQ(smallest.sample, arg);
  EXPECT_NEAR((smallest.robot_point - smallest.obstacle_point).norm(), std::abs(brute), 1e-9);
}

}  // namespace
}  // namespace cyber::plot

// The pictures of chains of one and of three joints (config/intake-pivot.toml,
// config/reefscape-2025-elevator-pivot-wrist.toml): the one joint's strip and the three joints'
// slices and projection hold what the collision world says, the picture draws each cell where its
// map puts it with the path kept clear of it, the time plots colour each joint by its index, and
// the world view draws the last link where the chain puts it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "cyber/config/load_config.hpp"
#include "cyber/planner.hpp"
#include "cyber/plot/trajectory_plot.hpp"
#include "cyber/plot/world_view.hpp"
#include "pixel_checks.hpp"
#include "shipped_robots.hpp"

namespace cyber::plot {
namespace {

using pixels::corner;
using pixels::Image;
using pixels::near;
using pixels::tempPath;
using planner::JointVector;
using planner::Point2;

const config::Config& robotConfig(const std::string& name) {
  static std::map<std::string, config::Config> loaded;
  if (!loaded.contains(name))
    loaded[name] = config::loadConfigFile(cyber::test::sourceFile("config/" + name + ".toml"));
  return loaded[name];
}
const config::Config& onePivot() { return robotConfig("intake-pivot"); }
const config::Config& elevatorPivotWrist() { return robotConfig("reefscape-2025-elevator-pivot-wrist"); }

JointVector pose(const config::Config& config, const std::string& name) {
  return cyber::test::namedPose(config, "none", name);
}

// A move at constant speed from `from` to `to` over 1 s, in `samples` samples, as a reader gives it.
TrajectoryPlotData straightMove(const JointVector& from, const JointVector& to, int samples = 201) {
  TrajectoryPlotData d;
  d.title = "straight";
  d.joints.resize(static_cast<size_t>(from.size()));
  for (int k = 0; k < samples; ++k) {
    const double s = static_cast<double>(k) / (samples - 1);
    d.time_s.push_back(s);
    for (size_t j = 0; j < d.joints.size(); ++j) {
      const auto i = static_cast<Eigen::Index>(j);
      JointSeries& series = d.joints[j];
      series.position.push_back(from[i] + s * (to[i] - from[i]));
      series.velocity.push_back(to[i] - from[i]);
      series.volts.push_back(1.0 + static_cast<double>(j));
      series.amps.push_back(2.0 + static_cast<double>(j));
    }
  }
  return d;
}

Move moveOfStraight(const JointVector& from, const JointVector& to) { return moveOf(straightMove(from, to, 51)); }

// The cell of `value` among `cells` over a range.
int cellOf(const planner::JointRange& r, double value, int cells) {
  return std::clamp(static_cast<int>(std::floor((value - r.min) / (r.max - r.min) * cells)), 0, cells - 1);
}

double cellCentre(const planner::JointRange& r, int i, int cells) {
  return r.min + (i + 0.5) * ((r.max - r.min) / cells);
}

bool blockedAt(const planner::RobotModel& robot, const JointVector& q) {
  const planner::CollisionWorld world(robot, robot.scenes[0], {});
  return world.distance(q).value < robot.clearance_m;
}

uint8_t cellValue(const CSpaceMap& m, int i, int j) { return m.blocked[static_cast<size_t>(i * m.cells[1] + j)]; }

// Whether cell (i, j) and its eight neighbours (within the map) hold the same value: its centre
// pixel is then covered by its own colour alone.
bool interior(const CSpaceMap& m, int i, int j) {
  for (int di = -1; di <= 1; ++di) {
    for (int dj = -1; dj <= 1; ++dj) {
      const int a = std::clamp(i + di, 0, m.cells[0] - 1), b = std::clamp(j + dj, 0, m.cells[1] - 1);
      if (cellValue(m, a, b) != cellValue(m, i, j)) return false;
    }
  }
  return true;
}

// A blocked cell drawn over white is (131, 131, 140), over a grid line darker; a free one white or
// a light grid line.
bool looksBlocked(const std::array<int, 3>& rgb) { return rgb[0] < 150 && std::abs(rgb[0] - rgb[1]) <= 4; }
bool looksFree(const std::array<int, 3>& rgb) { return rgb[0] > 200 && rgb[1] > 200 && rgb[2] > 200; }

// The picture's C-space box (render_png.cpp) and, for n maps stacked in it, map k's.
struct PixelBox {
  double x, y, w, h;
};
PixelBox mapBox(size_t k, size_t n) {
  constexpr double kX = 80, kY = 70, kW = 640, kH = 860, kGap = 70;
  const double h = (kH - kGap * static_cast<double>(n - 1)) / static_cast<double>(n);
  return {kX, kY + static_cast<double>(k) * (h + kGap), kW, h};
}

// The time plots' legend line of joint j in the position panel (render_png.cpp: box 860, 70,
// 700 wide; lines 16 px apart from 14 px down, 170 px in from the right edge).
Point2 positionLegend(int j) { return Point2(860 + 700 - 170 + 11, 70 + 14 + 16 * j - 4); }

constexpr uint8_t kJointColorBytes[3][3] = {{26, 89, 191}, {217, 89, 26}, {125, 84, 194}};
constexpr uint8_t kMarkerGreen[3] = {13, 102, 26};

TEST(OneJoint, TheStripIsBlockedAtTheCarpetAndFreeAtTheNamedPoses) {
  const config::Config& config = onePivot();
  const planner::RobotModel& robot = config.robot;
  const CSpaceView view = sampleCSpace(robot, 0, {});
  ASSERT_EQ(view.joints.size(), 1U);
  EXPECT_EQ(view.joints[0].name, "pivot");
  EXPECT_EQ(view.joints[0].unit, "rad");
  ASSERT_EQ(view.maps.size(), 1U);
  const CSpaceMap& m = view.maps[0];
  EXPECT_EQ(m.joints, (std::array<int, 2>{0, -1}));
  ASSERT_EQ(m.cells, (std::array<int, 2>{200, 1}));
  const planner::JointRange r = robot.range(0);
  // The head reaches the carpet at the lower hard stop (the config: clear of it from -0.81 rad).
  EXPECT_EQ(m.blocked.front(), kBlocked);
  EXPECT_EQ(m.blocked[static_cast<size_t>(cellOf(r, -0.83, 200))], kBlocked);
  for (const config::NamedPose& p : config.poses.front().poses) {
    EXPECT_EQ(m.blocked[static_cast<size_t>(cellOf(r, p.q[0], 200))], kFree) << p.name;
  }
  for (int i = 0; i < 200; ++i) {
    EXPECT_EQ(m.blocked[static_cast<size_t>(i)] == kBlocked, blockedAt(robot, JointVector{{cellCentre(r, i, 200)}}))
        << "cell " << i;
  }
}

TEST(ThreeJoints, TheSlicesHoldTheWristAtTheMovesStartAndGoal) {
  const config::Config& config = elevatorPivotWrist();
  const planner::RobotModel& robot = config.robot;
  const JointVector stow = pose(config, "STOW"), l3 = pose(config, "L3");
  TrajectoryPlotData d = straightMove(stow, l3);
  addRobotView(d, robot, 0, {});
  ASSERT_EQ(d.cspace.joints.size(), 3U);
  EXPECT_EQ(d.cspace.joints[2].name, "wrist");
  EXPECT_EQ(d.cspace.joints[0].voltage_limit_volts, 10.0);
  EXPECT_EQ(d.cspace.joints[2].current_limit_amps, 50.0);
  ASSERT_EQ(d.cspace.maps.size(), 2U);
  EXPECT_EQ(d.cspace.maps[0].caption, "wrist = 0.000 rad at the start");
  EXPECT_EQ(d.cspace.maps[1].caption, "wrist = -1.646 rad at the goal");
  int differ = 0;
  for (size_t k = 0; k < 2; ++k) {
    const CSpaceMap& m = d.cspace.maps[k];
    ASSERT_EQ(m.cells, (std::array<int, 2>{200, 200}));
    EXPECT_EQ(m.joints, (std::array<int, 2>{0, 1}));
    EXPECT_EQ(m.projected_joint, -1);
    const JointVector& end = k == 0 ? stow : l3;
    EXPECT_EQ(m.held[2], end[2]);
    EXPECT_EQ(cellValue(m, cellOf(robot.range(0), end[0], 200), cellOf(robot.range(1), end[1], 200)), kFree);
    for (int i = 0; i < 200; i += 13) {
      for (int j = 0; j < 200; j += 11) {
        const JointVector q{{cellCentre(robot.range(0), i, 200), cellCentre(robot.range(1), j, 200), m.held[2]}};
        EXPECT_EQ(cellValue(m, i, j) == kBlocked, blockedAt(robot, q)) << "map " << k << " cell " << i << "," << j;
        differ += cellValue(m, i, j) != cellValue(d.cspace.maps[1 - k], i, j) ? 1 : 0;
      }
    }
  }
  EXPECT_GT(differ, 0) << "the two wrist angles block the same cells";

  TrajectoryPlotData same = straightMove(pose(config, "L2"), pose(config, "L3"));
  addRobotView(same, robot, 0, {});
  ASSERT_EQ(same.cspace.maps.size(), 1U);
  EXPECT_EQ(same.cspace.maps[0].caption, "wrist = -1.646 rad at the start and the goal");
}

TEST(ThreeJoints, TheProjectionIsBlockedWhereEveryWristAngleIsAndLightWhereSomeAre) {
  const planner::RobotModel& robot = elevatorPivotWrist().robot;
  const CSpaceView view = sampleCSpace(robot, 0, {});
  ASSERT_EQ(view.maps.size(), 1U);
  const CSpaceMap& m = view.maps[0];
  EXPECT_EQ(m.projected_joint, 2);
  EXPECT_EQ(m.caption, "wrist projected out");
  ASSERT_EQ(m.cells, (std::array<int, 2>{100, 100}));
  std::array<int, 3> count{};
  for (uint8_t v : m.blocked) ++count[v];
  EXPECT_GT(count[kFree], 0);
  EXPECT_GT(count[kBlocked], 0);
  EXPECT_GT(count[kSomeBlocked], 0);
  const planner::JointRange& w = robot.range(2);
  for (int i = 0; i < 100; i += 9) {
    for (int j = 0; j < 100; j += 7) {
      int blocked = 0;
      for (int k = 0; k < kProjectionSamples; ++k) {
        const double wrist = w.min + (w.max - w.min) * k / (kProjectionSamples - 1);
        blocked +=
            blockedAt(robot,
                      JointVector{{cellCentre(robot.range(0), i, 100), cellCentre(robot.range(1), j, 100), wrist}})
                ? 1
                : 0;
      }
      const uint8_t want = blocked == 0 ? kFree : (blocked == kProjectionSamples ? kBlocked : kSomeBlocked);
      EXPECT_EQ(cellValue(m, i, j), want) << "cell " << i << "," << j << ": " << blocked << " wrist angles blocked";
    }
  }
}

// Every interior cell of every map at least 14 px from the path (60 px from its ends' labels, 3 px
// from the map's frame) has its map's grey or white at its centre pixel; returns how many were
// checked.
int expectCellsDrawn(const Image& image, const TrajectoryPlotData& d) {
  int checked = 0;
  const size_t n = d.cspace.maps.size();
  for (size_t k = 0; k < n; ++k) {
    const CSpaceMap& m = d.cspace.maps[k];
    const PixelBox b = mapBox(k, n);
    // Where the path is drawn in this map's pixels.
    std::vector<Point2> path;
    const bool strip = m.joints[1] < 0;
    const double t1 = d.time_s.back();
    for (size_t s = 0; s < d.time_s.size(); ++s) {
      const double x = strip ? d.time_s[s] / t1
                             : (d.joints[1].position[s] - d.cspace.joints[1].range.min) /
                                   (d.cspace.joints[1].range.max - d.cspace.joints[1].range.min);
      const planner::JointRange& r0 = d.cspace.joints[0].range;
      const double y = (d.joints[0].position[s] - r0.min) / (r0.max - r0.min);
      path.emplace_back(b.x + x * b.w, b.y + b.h - y * b.h);
    }
    for (int i = 0; i < m.cells[0]; i += 3) {
      for (int j = 0; j < m.cells[1]; j += 3) {
        if (!interior(m, i, j)) continue;
        const Point2 centre(b.x + (j + 0.5) * b.w / m.cells[1], b.y + b.h - (i + 0.5) * b.h / m.cells[0]);
        bool clear = (centre - path.front()).norm() > 60 && (centre - path.back()).norm() > 60 &&
                     std::min(centre.x() - b.x, b.x + b.w - centre.x()) > 3 &&
                     std::min(centre.y() - b.y, b.y + b.h - centre.y()) > 3;
        for (const Point2& p : path) clear = clear && (centre - p).norm() > 14;
        if (!clear) continue;
        const auto rgb = image.at(centre.x(), centre.y());
        if (cellValue(m, i, j) == kBlocked) {
          EXPECT_TRUE(looksBlocked(rgb)) << "map " << k << " cell " << i << "," << j << " got " << rgb[0] << ","
                                         << rgb[1] << "," << rgb[2];
        } else {
          EXPECT_TRUE(looksFree(rgb)) << "map " << k << " cell " << i << "," << j << " got " << rgb[0] << "," << rgb[1]
                                      << "," << rgb[2];
        }
        ++checked;
      }
    }
  }
  return checked;
}

TEST(OneJoint, ThePictureDrawsTheStripOverTimeAndOneSeries) {
  const config::Config& config = onePivot();
  TrajectoryPlotData d = straightMove(pose(config, "STOW"), pose(config, "DEPLOYED"));
  addRobotView(d, config.robot, 0, {});
  const std::string path = tempPath("one_joint_plot");
  const auto written = renderTrajectoryPng(d, path);
  ASSERT_TRUE(written.ok()) << written.error().message;
  const Image image(path);
  ASSERT_TRUE(image.ok());
  EXPECT_GT(expectCellsDrawn(image, d), 20);
  EXPECT_TRUE(near(image.at(positionLegend(0).x(), positionLegend(0).y()), kJointColorBytes[0]));
  EXPECT_TRUE(looksFree(image.at(positionLegend(1).x(), positionLegend(1).y()))) << "a second series";
  std::filesystem::remove(path);
}

TEST(ThreeJoints, ThePictureDrawsBothSlicesAndAThirdSeriesInItsOwnColour) {
  const config::Config& config = elevatorPivotWrist();
  TrajectoryPlotData d = straightMove(pose(config, "STOW"), pose(config, "L3"));
  addRobotView(d, config.robot, 0, {});
  const std::string path = tempPath("three_joint_plot");
  const auto written = renderTrajectoryPng(d, path);
  ASSERT_TRUE(written.ok()) << written.error().message;
  const Image image(path);
  ASSERT_TRUE(image.ok());
  EXPECT_GT(expectCellsDrawn(image, d), 200);
  for (int j = 0; j < 3; ++j) {
    const auto rgb = image.at(positionLegend(j).x(), positionLegend(j).y());
    EXPECT_TRUE(near(rgb, kJointColorBytes[j])) << "joint " << j << " got " << rgb[0] << "," << rgb[1] << "," << rgb[2];
  }
  std::filesystem::remove(path);
}

TEST(ThreeJoints, DataWithoutASeriesPerJointIsNotDrawn) {
  const config::Config& config = elevatorPivotWrist();
  TrajectoryPlotData d = straightMove(JointVector{{0.1, 1.5}}, JointVector{{0.2, 1.6}});
  addRobotView(d, config.robot, 0, {});
  const auto written = renderTrajectoryPng(d, "/tmp/never.png");
  ASSERT_EQ(written.status(), PlotStatus::kNothingToDraw);
  EXPECT_EQ(written.error().message, "/tmp/never.png: 2 joint series of 201 samples for 3 joints: not one per joint");
}

// The corners of the last link's outline farthest from its joint, at pose q: inside them the
// link's colour, outside not (but where the pose's clearance is drawn in red).
void expectLastLinkCorners(const planner::RobotModel& robot, const JointVector& q, const std::string& label) {
  const std::string path = tempPath("world_" + label);
  const auto written = renderWorldPng(robot, 0, {}, q, label, path);
  ASSERT_TRUE(written.ok()) << written.error().message;
  const Image image(path);
  ASSERT_TRUE(image.ok());
  const WorldCanvas c = worldPngCanvas(robot);
  const int last = robot.jointCount() - 1;
  const auto& color = kWorldColors.links[last];
  const planner::LinkFrame frame = planner::linkFrames(robot.joints, q).back();
  const planner::ConvexPolygon& outline = robot.links.back().polygons.back();
  ASSERT_EQ(robot.links.back().joint, last);
  double far = 0;
  for (const Point2& v : outline.vertices()) far = std::max(far, v.x());
  std::vector<Point2> world;
  for (const Point2& v : outline.vertices()) world.push_back(frame.toWorld(v));
  const Point2 witness = planner::CollisionWorld(robot, robot.scenes[0], {}).distance(q).witness_robot;
  int checked = 0;
  for (size_t i = 0; i < world.size(); ++i) {
    if (outline.vertices()[i].x() < far - 1e-9) continue;
    if ((world[i] - witness).norm() * c.scale < 10) continue;
    const Point2 in = corner(c, world, i, 2.5);
    EXPECT_TRUE(near(image.at(in.x(), in.y()), color)) << label << " corner " << outline.vertices()[i].transpose();
    const Point2 out = corner(c, world, i, -4.0);
    EXPECT_FALSE(near(image.at(out.x(), out.y()), color)) << label << " corner " << outline.vertices()[i].transpose();
    ++checked;
  }
  EXPECT_GE(checked, 1) << label;
  std::filesystem::remove(path);
}

TEST(ThreeJoints, TheWorldViewDrawsTheEffectorWhereTheWristPutsIt) {
  const config::Config& config = elevatorPivotWrist();
  for (const char* name : {"STOW", "L3", "ALGAE_HIGH", "PROCESSOR"}) {
    expectLastLinkCorners(config.robot, pose(config, name), name);
  }
}

TEST(OneJoint, TheWorldViewDrawsTheIntakeHeadWhereThePivotPutsIt) {
  const config::Config& config = onePivot();
  for (const char* name : {"STOW", "DEPLOYED", "L1"}) expectLastLinkCorners(config.robot, pose(config, name), name);
}

TEST(ThreeJoints, FilmstripsAndAnimationsTakeMovesOfThreeJointsOnly) {
  const config::Config& config = elevatorPivotWrist();
  const Move move = moveOfStraight(pose(config, "STOW"), pose(config, "L3"));
  ASSERT_EQ(move.q.size(), 51U);
  EXPECT_EQ(move.q.back(), pose(config, "L3"));
  const std::string path = tempPath("three_joint_film");
  const auto strip = renderFilmstripPng(config.robot, 0, {}, move, 4, "STOW -> L3", path);
  ASSERT_TRUE(strip.ok()) << strip.error().message;
  EXPECT_TRUE(Image(path).ok());
  const auto anim = renderAnimationApng(config.robot, 0, {}, move, 5, "STOW -> L3", path);
  ASSERT_TRUE(anim.ok()) << anim.error().message;
  std::filesystem::remove(path);
  const Move two = moveOfStraight(JointVector{{0.1, 1.5}}, JointVector{{0.2, 1.6}});
  const auto refused = renderFilmstripPng(config.robot, 0, {}, two, 4, "two", "/tmp/never.png");
  ASSERT_EQ(refused.status(), PlotStatus::kNothingToDraw);
  EXPECT_EQ(refused.error().message, "/tmp/never.png: the move's poses have 2 values, the robot 3 joints");
}

TEST(OneJoint, ThePreviewMarksEachPoseAcrossTheStrip) {
  const config::Config& config = onePivot();
  std::vector<NamedJointPose> poses;
  for (const config::NamedPose& p : config.poses.front().poses) poses.push_back({p.name, p.q});
  const std::string path = tempPath("one_joint_preview");
  const auto written = renderConfigPreviewPng(config.robot, 0, {}, poses, "intake-pivot", path);
  ASSERT_TRUE(written.ok()) << written.error().message;
  const Image image(path);
  ASSERT_TRUE(image.ok());
  // The strip: 160 px wide at (760, 60), 810 px tall over the pivot's range (world_view.cpp).
  const planner::JointRange r = config.robot.range(0);
  for (const NamedJointPose& p : poses) {
    const double y = 60 + 810 - (p.q[0] - r.min) / (r.max - r.min) * 810;
    EXPECT_TRUE(near(image.at(760 + 80, y), kMarkerGreen)) << p.name;
  }
  std::filesystem::remove(path);
}

TEST(ThreeJoints, ThePreviewDrawsTheProjection) {
  const config::Config& config = elevatorPivotWrist();
  std::vector<NamedJointPose> poses;
  for (const config::NamedPose& p : config.poses.front().poses) poses.push_back({p.name, p.q});
  const std::string path = tempPath("three_joint_preview");
  const auto written = renderConfigPreviewPng(config.robot, 0, {}, poses, "elevator-pivot-wrist", path);
  ASSERT_TRUE(written.ok()) << written.error().message;
  EXPECT_TRUE(Image(path).ok());
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace cyber::plot

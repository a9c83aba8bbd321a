#include "cyber/plot/world_view.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "cyber/planner.hpp"
#include "cyber/plot/apng_writer.hpp"
#include "drawing.hpp"

namespace cyber::plot {
namespace {

using detail::Rgb;
using detail::setColor;
using detail::text;
using planner::ConvexPolygon;
using planner::JointVector;
using planner::Point2;

Rgb rgb(const uint8_t (&c)[3]) { return Rgb{c[0] / 255.0, c[1] / 255.0, c[2] / 255.0}; }
constexpr Rgb kOutline{0.15, 0.15, 0.18};
constexpr Rgb kRail{0.35, 0.45, 0.70};
constexpr Rgb kClearance{0.85, 0.05, 0.10};

struct Surface {
  cairo_surface_t* surface;
  cairo_t* cr;
  Surface(int w, int h) : surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h)), cr(cairo_create(surface)) {
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  }
  ~Surface() {
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
  }
  Surface(const Surface&) = delete;
  Surface& operator=(const Surface&) = delete;
};

// A robot polygon with the link it moves with and the colour it is drawn in.
struct RobotPart {
  int link = 0;
  const ConvexPolygon* polygon = nullptr;
  const uint8_t* color = nullptr;
};

// Every link outline, then the held pieces', as CollisionWorld sees them.
std::vector<RobotPart> robotParts(const planner::RobotModel& robot, planner::HeldPieces pieces) {
  std::vector<RobotPart> out;
  for (const planner::LinkGeometry& link : robot.links) {
    for (const ConvexPolygon& p : link.polygons) out.push_back({link.joint, &p, kWorldColors.links[link.joint]});
  }
  for (size_t i = 0; i < robot.pieces.size(); ++i) {
    if (!pieces.holds(static_cast<int>(i))) continue;
    const planner::GamePiece& piece = robot.pieces[i];
    for (const ConvexPolygon& p : piece.polygons) out.push_back({piece.joint, &p, kWorldColors.pieces[i % 4]});
  }
  return out;
}

// The farthest point along the last link's x axis of what moves with it: the tip traced and
// labelled.
double lastLinkReach(const planner::RobotModel& robot, planner::HeldPieces pieces) {
  double reach = 0;
  for (const RobotPart& part : robotParts(robot, pieces)) {
    if (part.link != robot.jointCount() - 1) continue;
    for (const Point2& v : part.polygon->vertices()) reach = std::max(reach, v.x());
  }
  return reach;
}

void polygonPath(cairo_t* cr, const WorldCanvas& c, const std::vector<Point2>& world) {
  for (size_t i = 0; i < world.size(); ++i) {
    const double x = c.px(world[i].x()), y = c.py(world[i].y());
    if (i == 0) {
      cairo_move_to(cr, x, y);
    } else {
      cairo_line_to(cr, x, y);
    }
  }
  cairo_close_path(cr);
}

void fillOutlined(cairo_t* cr, Rgb fill, double alpha) {
  setColor(cr, fill, alpha);
  cairo_fill_preserve(cr);
  setColor(cr, kOutline, alpha);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
}

// Sky, obstacles, the rail and metre ticks, clipped to the canvas (the clip stays set).
void drawScene(cairo_t* cr, const WorldCanvas& c, const planner::RobotModel& robot, int scene) {
  cairo_save(cr);
  cairo_rectangle(cr, c.box_x, c.box_y, c.box_w, c.box_h);
  cairo_clip(cr);
  setColor(cr, rgb(kWorldColors.sky));
  cairo_paint(cr);
  if (scene >= 0 && scene < static_cast<int>(robot.scenes.size())) {
    const planner::Scene& drawn = robot.scenes[static_cast<size_t>(scene)];
    for (const auto* list : {&drawn.obstacles, &drawn.fixed}) {
      for (const auto& o : *list) {
        polygonPath(cr, c, o.polygon.vertices());
        fillOutlined(cr, rgb(kWorldColors.obstacle), 1.0);
      }
    }
  }
  // A first joint that slides is drawn as its rail (a later one moves with the links).
  const planner::ChainJoint& first = robot.joints[0];
  if (first.type == planner::JointType::kPrismatic) {
    const Point2 dir(std::cos(first.axis_rad), std::sin(first.axis_rad));
    const Point2 a = first.origin_m + first.range.min * dir;
    const Point2 b = first.origin_m + first.range.max * dir;
    setColor(cr, kRail, 0.5);
    cairo_set_line_width(cr, 5.0);
    cairo_move_to(cr, c.px(a.x()), c.py(a.y()));
    cairo_line_to(cr, c.px(b.x()), c.py(b.y()));
    cairo_stroke(cr);
  }
  cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
  for (double x = std::ceil(c.x0 * 2) / 2; x <= c.x1; x += 0.5)
    text(cr, c.px(x), c.box_y + c.box_h - 4, fmt::format("{:.1f}", x), 10, true);
  for (double y = std::ceil(c.y0 * 2) / 2; y <= c.y1; y += 0.5)
    text(cr, c.box_x + 3, c.py(y) + 4, fmt::format("{:.1f}", y), 10);
}

void endScene(cairo_t* cr, const WorldCanvas& c) {
  cairo_restore(cr);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, c.box_x, c.box_y, c.box_w, c.box_h);
  cairo_stroke(cr);
}

void drawRobot(cairo_t* cr, const WorldCanvas& c, const planner::RobotModel& robot, planner::HeldPieces pieces,
               const JointVector& q, double alpha) {
  const auto frames = planner::linkFrames(robot.joints, q);
  for (const RobotPart& part : robotParts(robot, pieces)) {
    std::vector<Point2> world;
    for (const Point2& v : part.polygon->vertices()) world.push_back(frames[static_cast<size_t>(part.link)].toWorld(v));
    polygonPath(cr, c, world);
    fillOutlined(cr, Rgb{part.color[0] / 255.0, part.color[1] / 255.0, part.color[2] / 255.0}, alpha);
  }
  // The joints: each link frame's origin.
  setColor(cr, kOutline, alpha);
  for (const planner::LinkFrame& frame : frames) {
    cairo_arc(cr, c.px(frame.origin_m.x()), c.py(frame.origin_m.y()), 3.0, 0, 2 * M_PI);
    cairo_fill(cr);
  }
}

void drawClearance(cairo_t* cr, const WorldCanvas& c, const Point2& robot_point, const Point2& obstacle_point,
                   double distance_m, const std::string& label) {
  setColor(cr, kClearance);
  cairo_set_line_width(cr, 2.0);
  cairo_move_to(cr, c.px(robot_point.x()), c.py(robot_point.y()));
  cairo_line_to(cr, c.px(obstacle_point.x()), c.py(obstacle_point.y()));
  cairo_stroke(cr);
  for (const Point2& p : {robot_point, obstacle_point}) {
    cairo_arc(cr, c.px(p.x()), c.py(p.y()), 3.0, 0, 2 * M_PI);
    cairo_fill(cr);
  }
  const Point2 mid = (robot_point + obstacle_point) / 2;
  text(cr, c.px(mid.x()) + 8, c.py(mid.y()) - 6, fmt::format("{}{:.3f} m", label, distance_m), 12);
}

// The farthest robot point along the last link's x axis, traced over the move.
void drawTipTrace(cairo_t* cr, const WorldCanvas& c, const planner::RobotModel& robot, planner::HeldPieces pieces,
                  const Move& move) {
  const double reach = lastLinkReach(robot, pieces);
  setColor(cr, Rgb{0.05, 0.55, 0.15}, 0.8);
  cairo_set_line_width(cr, 1.5);
  for (size_t k = 0; k < move.q.size(); ++k) {
    const Point2 tip = planner::linkFrames(robot.joints, move.q[k]).back().toWorld(Point2(reach, 0));
    if (k == 0) {
      cairo_move_to(cr, c.px(tip.x()), c.py(tip.y()));
    } else {
      cairo_line_to(cr, c.px(tip.x()), c.py(tip.y()));
    }
  }
  cairo_stroke(cr);
}

JointVector at(const Move& move, double t) {
  const auto it = std::lower_bound(move.time_s.begin(), move.time_s.end(), t);
  if (it == move.time_s.begin()) return move.q.front();
  if (it == move.time_s.end()) return move.q.back();
  const size_t k = static_cast<size_t>(it - move.time_s.begin());
  const double span = move.time_s[k] - move.time_s[k - 1];
  const double s = span > 0 ? (t - move.time_s[k - 1]) / span : 1.0;
  return move.q[k - 1] + s * (move.q[k] - move.q[k - 1]);
}

planner::SignedDistance distanceAt(const planner::CollisionWorld& world, const JointVector& q) {
  return world.distance(q);
}

// Frame times: `count` even steps over the move, the one nearest the time of smallest clearance
// moved onto it (the first and last stay: start and goal).
std::vector<double> frameTimes(const Move& move, int count, double clearance_time_s) {
  std::vector<double> times;
  const double duration = move.time_s.empty() ? 0 : move.time_s.back() - move.time_s.front();
  const double t0 = move.time_s.empty() ? 0 : move.time_s.front();
  for (int k = 0; k < count; ++k) times.push_back(t0 + (count > 1 ? duration * k / (count - 1) : 0));
  size_t nearest = 0;
  for (size_t k = 0; k < times.size(); ++k) {
    if (std::abs(times[k] - clearance_time_s) < std::abs(times[nearest] - clearance_time_s)) nearest = k;
  }
  if (nearest == 0 || nearest + 1 == times.size()) {
    if (std::abs(times[nearest] - clearance_time_s) > 1e-9) times.push_back(clearance_time_s);
  } else {
    times[nearest] = clearance_time_s;
  }
  std::sort(times.begin(), times.end());
  return times;
}

// kNothingToDraw unless the move has samples (as many poses as times), each of the robot's joint
// count.
Result<Done, PlotStatus> checkMove(const planner::RobotModel& robot, const Move& move, const std::string& path) {
  if (move.q.empty() || move.q.size() != move.time_s.size()) {
    return detail::pictureError(PlotStatus::kNothingToDraw, path, "the move has no samples");
  }
  for (const JointVector& q : move.q) {
    if (q.size() != robot.jointCount()) {
      return detail::pictureError(
          PlotStatus::kNothingToDraw, path,
          fmt::format("the move's poses have {} values, the robot {} joints", q.size(), robot.jointCount()));
    }
  }
  return Done{};
}

// One frame of a move: scene, tip trace, the robot at t, the smallest clearance when at it.
void drawMoveFrame(cairo_t* cr, const WorldCanvas& c, const planner::RobotModel& robot, int scene,
                   planner::HeldPieces pieces, const Move& move, const planner::CollisionWorld& world,
                   const Clearance& smallest, double t, bool mark_always, bool long_label) {
  drawScene(cr, c, robot, scene);
  drawTipTrace(cr, c, robot, pieces, move);
  const JointVector q = at(move, t);
  drawRobot(cr, c, robot, pieces, q, 1.0);
  const bool at_smallest = std::abs(t - smallest.time_s) < 1e-9;
  if (at_smallest || mark_always) {
    drawClearance(cr, c, smallest.robot_point, smallest.obstacle_point, smallest.distance_m, "");
  }
  if (!at_smallest) {
    const planner::SignedDistance d = distanceAt(world, q);
    if (d.exact || std::isfinite(d.value)) {
      setColor(cr, Rgb{0.2, 0.2, 0.2}, 0.7);
      cairo_set_line_width(cr, 1.0);
      cairo_move_to(cr, c.px(d.witness_robot.x()), c.py(d.witness_robot.y()));
      cairo_line_to(cr, c.px(d.witness_obstacle.x()), c.py(d.witness_obstacle.y()));
      cairo_stroke(cr);
    }
  }
  endScene(cr, c);
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, c.box_x + c.box_w / 2, c.box_y + 16, fmt::format("t = {:.2f} s", t - move.time_s.front()), 13, true);
  if (long_label) {
    setColor(cr, kClearance);
    text(cr, c.box_x + c.box_w / 2, c.box_y + 34,
         fmt::format("smallest clearance {:.3f} m at {:.2f} s", smallest.distance_m,
                     smallest.time_s - move.time_s.front()),
         12, true);
  }
  if (at_smallest) {
    setColor(cr, kClearance);
    cairo_set_line_width(cr, 3.0);
    cairo_rectangle(cr, c.box_x - 2, c.box_y - 2, c.box_w + 4, c.box_h + 4);
    cairo_stroke(cr);
  }
}

}  // namespace

WorldCanvas fitWorld(const planner::RobotModel& robot, double box_x, double box_y, double box_w, double box_h) {
  // Everything the robot can sweep: its polygons (every piece held) over a grid of joint values,
  // kSamples per joint (9^3 poses for three joints: transforms only, no distances).
  constexpr int kSamples = 9;
  constexpr double kMargin = 0.1;
  Point2 lo = Point2::Constant(std::numeric_limits<double>::infinity());
  Point2 hi = -lo;
  const std::vector<RobotPart> parts = robotParts(robot, robot.allPieces());
  const int n = robot.jointCount();
  int poses = 1;
  for (int j = 0; j < n; ++j) poses *= kSamples;
  for (int index = 0; index < poses; ++index) {
    JointVector q(n);
    for (int j = 0, rest = index; j < n; ++j, rest /= kSamples) {
      const double f = static_cast<double>(rest % kSamples) / (kSamples - 1);
      q[j] = robot.range(j).min + f * (robot.range(j).max - robot.range(j).min);
    }
    const auto frames = planner::linkFrames(robot.joints, q);
    for (const RobotPart& part : parts) {
      for (const Point2& v : part.polygon->vertices()) {
        const Point2 w = frames[part.link].toWorld(v);
        lo = lo.cwiseMin(w);
        hi = hi.cwiseMax(w);
      }
    }
  }
  double x0 = lo.x() - kMargin, x1 = hi.x() + kMargin;
  double y0 = std::max(lo.y() - kMargin, -kMargin), y1 = hi.y() + kMargin;  // below the floor is nothing to see
  const double scale = std::min(box_w / (x1 - x0), box_h / (y1 - y0));
  const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  WorldCanvas c;
  c.box_x = box_x, c.box_y = box_y, c.box_w = box_w, c.box_h = box_h, c.scale = scale;
  c.x0 = cx - box_w / scale / 2, c.x1 = cx + box_w / scale / 2;
  c.y0 = cy - box_h / scale / 2, c.y1 = cy + box_h / scale / 2;
  return c;
}

Move moveOf(const TrajectoryPlotData& data) {
  Move move;
  move.time_s = data.time_s;
  for (size_t k = 0; k < data.time_s.size(); ++k) {
    JointVector q(static_cast<Eigen::Index>(data.joints.size()));
    for (size_t j = 0; j < data.joints.size(); ++j) q[static_cast<Eigen::Index>(j)] = data.joints[j].position[k];
    move.q.push_back(q);
  }
  return move;
}

Clearance smallestClearance(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces, const Move& move) {
  Clearance best;
  best.distance_m = std::numeric_limits<double>::infinity();
  if (scene < 0 || scene >= static_cast<int>(robot.scenes.size())) return best;
  const planner::CollisionWorld world(robot, robot.scenes[static_cast<size_t>(scene)], pieces);
  for (size_t k = 0; k < move.q.size(); ++k) {
    const planner::SignedDistance d = world.distance(move.q[k]);
    if (d.value < best.distance_m) {
      best = Clearance{d.value, move.time_s[k], k, d.witness_robot, d.witness_obstacle};
    }
  }
  return best;
}

WorldCanvas worldPngCanvas(const planner::RobotModel& robot) {
  return fitWorld(robot, 20, 50, kWorldWidth - 40, kWorldHeight - 70);
}

Result<Done, PlotStatus> renderWorldPng(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces,
                                        const JointVector& q, const std::string& title, const std::string& path) {
  Surface s(kWorldWidth, kWorldHeight);
  const WorldCanvas c = worldPngCanvas(robot);
  drawScene(s.cr, c, robot, scene);
  drawRobot(s.cr, c, robot, pieces, q, 1.0);
  if (scene >= 0 && scene < static_cast<int>(robot.scenes.size())) {
    const planner::CollisionWorld world(robot, robot.scenes[static_cast<size_t>(scene)], pieces);
    const planner::SignedDistance d = world.distance(q);
    if (std::isfinite(d.value)) drawClearance(s.cr, c, d.witness_robot, d.witness_obstacle, d.value, "clearance ");
  }
  endScene(s.cr, c);
  cairo_set_source_rgb(s.cr, 0, 0, 0);
  text(s.cr, kWorldWidth / 2.0, 32, title, 16, true);
  return detail::writePng(s.surface, path);
}

Result<Done, PlotStatus> renderFilmstripPng(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces,
                                            const Move& move, int frames, const std::string& title,
                                            const std::string& path) {
  if (auto checked = checkMove(robot, move, path); !checked) return checked;
  const Clearance smallest = smallestClearance(robot, scene, pieces, move);
  const std::vector<double> times = frameTimes(move, std::max(2, frames), smallest.time_s);
  constexpr int kPanelW = 250, kPanelH = 360, kGap = 12;
  const int width = static_cast<int>(times.size()) * (kPanelW + kGap) + kGap;
  Surface s(width, kPanelH + 90);
  const planner::Scene& sc = robot.scenes.at(static_cast<size_t>(scene));
  const planner::CollisionWorld world(robot, sc, pieces);
  for (size_t i = 0; i < times.size(); ++i) {
    const WorldCanvas c = fitWorld(robot, kGap + static_cast<double>(i) * (kPanelW + kGap), 50, kPanelW, kPanelH);
    drawMoveFrame(s.cr, c, robot, scene, pieces, move, world, smallest, times[i], false, false);
  }
  cairo_set_source_rgb(s.cr, 0, 0, 0);
  text(s.cr, width / 2.0, 30, title, 16, true);
  text(s.cr, width / 2.0, kPanelH + 78,
       fmt::format("smallest clearance {:.3f} m at t = {:.2f} s (red frame); green: path of the chain's tip",
                   smallest.distance_m, smallest.time_s - move.time_s.front()),
       13, true);
  return detail::writePng(s.surface, path);
}

Result<Done, PlotStatus> renderAnimationApng(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces,
                                             const Move& move, int fps, const std::string& title,
                                             const std::string& path) {
  if (auto checked = checkMove(robot, move, path); !checked) return checked;
  const Clearance smallest = smallestClearance(robot, scene, pieces, move);
  const double duration = move.time_s.back() - move.time_s.front();
  constexpr int kMaxFrames = 200;
  const int count = std::clamp(static_cast<int>(std::ceil(duration * fps)) + 1, 2, kMaxFrames);
  const std::vector<double> times = frameTimes(move, count, smallest.time_s);
  const planner::CollisionWorld world(robot, robot.scenes.at(static_cast<size_t>(scene)), pieces);
  constexpr int kW = 420, kH = 600;
  std::vector<std::unique_ptr<Surface>> surfaces;
  std::vector<cairo_surface_t*> frames;
  for (double t : times) {
    surfaces.push_back(std::make_unique<Surface>(kW, kH));
    Surface& s = *surfaces.back();
    const WorldCanvas c = fitWorld(robot, 10, 40, kW - 20, kH - 50);
    drawMoveFrame(s.cr, c, robot, scene, pieces, move, world, smallest, t, true, true);
    cairo_set_source_rgb(s.cr, 0, 0, 0);
    text(s.cr, kW / 2.0, 26, title, 13, true);
    cairo_surface_flush(s.surface);
    frames.push_back(s.surface);
  }
  return writeApng(frames, std::max(1, 1000 / std::max(1, fps)), path);
}

Result<Done, PlotStatus> renderConfigPreviewPng(const planner::RobotModel& robot, int scene, planner::HeldPieces pieces,
                                                const std::vector<NamedJointPose>& poses, const std::string& title,
                                                const std::string& path) {
  constexpr int kW = 1500, kH = 940;
  Surface s(kW, kH);
  const WorldCanvas c = fitWorld(robot, 20, 60, 620, kH - 80);
  drawScene(s.cr, c, robot, scene);
  const double reach = lastLinkReach(robot, pieces);
  for (const NamedJointPose& p : poses) drawRobot(s.cr, c, robot, pieces, p.q, 0.55);
  cairo_set_source_rgb(s.cr, 0, 0, 0);
  for (const NamedJointPose& p : poses) {
    const Point2 tip = planner::linkFrames(robot.joints, p.q).back().toWorld(Point2(reach + 0.03, 0));
    text(s.cr, c.px(tip.x()), c.py(tip.y()), p.name, 11, true);
  }
  endScene(s.cr, c);
  detail::drawCSpaceWithPoses(s.cr, sampleCSpace(robot, scene, pieces), poses, 760, 60, 700, kH - 130);
  cairo_set_source_rgb(s.cr, 0, 0, 0);
  text(s.cr, kW / 2.0, 34, title, 18, true);
  return detail::writePng(s.surface, path);
}

}  // namespace cyber::plot

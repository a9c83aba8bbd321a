#include "cyber/planner/collision_world.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/signed_distance.hpp"

namespace cyber::planner {
namespace {

// Outward unit normals of a counter-clockwise polygon, edge i from vertex i to i+1.
std::vector<Point2> outwardNormals(const std::vector<Point2>& v) {
  std::vector<Point2> normals;
  normals.reserve(v.size());
  for (size_t i = 0; i < v.size(); ++i) {
    const Point2 e = v[(i + 1) % v.size()] - v[i];
    normals.emplace_back(Point2(e.y(), -e.x()).normalized());
  }
  return normals;
}

// Distance from a point to an axis-aligned box (0 inside).
double pointBoxDistance(const Point2& p, const Point2& lo, const Point2& hi) {
  const double dx = std::max({lo.x() - p.x(), 0.0, p.x() - hi.x()});
  const double dy = std::max({lo.y() - p.y(), 0.0, p.y() - hi.y()});
  return std::sqrt(dx * dx + dy * dy);
}

// The largest distance from its parent link's origin of a point p of a joint's link, over the
// joint's range: for a revolute joint, |origin| + |p| (it may turn p to point away); for a
// prismatic one the distance is convex in q, so its largest value is at an end of the range.
double farthestFromParentOrigin(const ChainJoint& joint, const Point2& p) {
  if (joint.type == JointType::kRevolute) return joint.origin_m.norm() + p.norm();
  const Point2 travel(std::cos(joint.axis_rad), std::sin(joint.axis_rad));
  return std::max((joint.origin_m + joint.range.min * travel + p).norm(),
                  (joint.origin_m + joint.range.max * travel + p).norm());
}

// A bound on the distance from joint j's axis (its link's origin) of a point p of link k >= j,
// over the ranges of the joints after j: the exact largest distance from link k-1's origin, then
// the triangle inequality through each joint's origin between (docs/algorithm.md section 2.1).
double farthestFromAxis(const JointChain& chain, int j, int k, const Point2& p) {
  if (k == j) return p.norm();
  double reach = farthestFromParentOrigin(chain[k], p);
  for (int m = k - 1; m > j; --m) reach += farthestFromParentOrigin(chain[m], Point2::Zero());
  return reach;
}

}  // namespace

CollisionWorld::CollisionWorld(const RobotModel& model, const Scene& scene, HeldPieces pieces, double scene_offset_m)
    : CollisionWorld(model, scene, pieces, JointRange{scene_offset_m, scene_offset_m}) {}

CollisionWorld::CollisionWorld(const RobotModel& model, const Scene& scene, HeldPieces pieces, const JointRange& band)
    : pieces_(pieces), chain_(model.joints) {
  const int n = model.jointCount();
  PerJoint<double> reach_m(n, 0.0);  // of joint j's axis, over the links from j on
  auto add_robot = [&](int link, const std::vector<ConvexPolygon>& polygons) {
    for (const ConvexPolygon& polygon : polygons) {
      if (polygon.empty()) continue;
      RobotPart part;
      part.link = link;
      part.vertices = polygon.vertices();
      part.normals = outwardNormals(part.vertices);
      for (const Point2& v : part.vertices) part.centre += v;
      part.centre /= static_cast<double>(part.vertices.size());
      for (const Point2& v : part.vertices) {
        part.radius = std::max(part.radius, (v - part.centre).norm());
        for (int j = 0; j <= link; ++j) reach_m[j] = std::max(reach_m[j], farthestFromAxis(chain_, j, link, v));
      }
      robot_.push_back(std::move(part));
    }
  };
  for (const LinkGeometry& link : model.links) add_robot(link.joint, link.polygons);
  for (size_t i = 0; i < model.pieces.size(); ++i) {
    if (pieces.holds(static_cast<int>(i))) add_robot(model.pieces[i].joint, model.pieces[i].polygons);
  }
  point_speed_.resize(n);
  for (int j = 0; j < n; ++j) point_speed_[j] = chain_[j].type == JointType::kPrismatic ? 1.0 : reach_m[j];

  auto add_obstacle = [&](const NamedPolygon& named, const JointRange& shift_m) {
    if (named.polygon.empty()) return;
    Obstacle obstacle;
    obstacle.vertices = named.polygon.sweptAlongX(shift_m.min, shift_m.max).vertices();
    obstacle.normals = outwardNormals(obstacle.vertices);
    obstacle.box_min = obstacle.box_max = obstacle.vertices.front();
    for (const Point2& v : obstacle.vertices) {
      obstacle.box_min = obstacle.box_min.cwiseMin(v);
      obstacle.box_max = obstacle.box_max.cwiseMax(v);
    }
    obstacles_.push_back(std::move(obstacle));
  };
  for (const NamedPolygon& named : scene.obstacles) add_obstacle(named, band);
  for (const NamedPolygon& named : scene.fixed) add_obstacle(named, JointRange{});
}

bool CollisionWorld::pairDistance(size_t r, size_t o, const ChainPose& pose, double bound, PlacedPolygon& placed,
                                  SignedDistance& out) const {
  const RobotPart& part = robot_[r];
  const LinkFrame& frame = pose.frames[part.link];
  const Obstacle& obstacle = obstacles_[o];
  const int n = static_cast<int>(part.vertices.size());
  // Circle against box bounds the distance of separated shapes only, so it prunes only when
  // positive (a penetration can be deeper than the circle's radius).
  const double circle_bound =
      pointBoxDistance(frame.toWorld(part.centre), obstacle.box_min, obstacle.box_max) - part.radius;
  if (circle_bound > 0.0 && circle_bound >= bound) {
    out.value = circle_bound;
    out.exact = false;
    return false;
  }
  const WorldPolygonView obstacle_view{obstacle.vertices.data(), obstacle.normals.data(),
                                       static_cast<int>(obstacle.vertices.size())};
  PairDistance pair;
  if (n <= kStackVertices) {
    if (placed.placed_part != static_cast<int>(r)) {
      for (int i = 0; i < n; ++i) {
        placed.vertices[i] = frame.toWorld(part.vertices[static_cast<size_t>(i)]);
        placed.normals[i] = frame.rotate(part.normals[static_cast<size_t>(i)]);
      }
      placed.placed_part = static_cast<int>(r);
    }
    pair = signedDistance(WorldPolygonView{placed.vertices, placed.normals, n}, obstacle_view, bound);
  } else {
    pair = signedDistance(LinkPolygonView{part.vertices.data(), part.normals.data(), n, &frame}, obstacle_view, bound);
  }
  out.value = pair.value;
  out.exact = pair.exact && pair.value < bound;
  if (!out.exact) return false;
  out.witness_robot = pair.witness_a;
  out.witness_obstacle = pair.witness_b;
  out.robot_polygon = static_cast<int>(r);
  out.obstacle = static_cast<int>(o);
  // Rigid motion of the robot: d changes by -normal . (velocity of the robot's witness point),
  // with normal pointing from the robot to the obstacle (envelope theorem for the separated
  // case; for overlap the active axis and vertex move the same way).
  out.gradient = -(pose.pointJacobian(part.link, pair.witness_a).transpose() * pair.normal);
  return true;
}

SignedDistance CollisionWorld::distance(const JointVector& q, double cutoff) const {
  SignedDistance best;
  const ChainPose pose = poseAt(q);
  // `bound` is what a pair must beat: the best exact value so far, or the cutoff.
  double bound = cutoff;
  double smallest_lower_bound = std::numeric_limits<double>::infinity();
  PlacedPolygon placed;
  SignedDistance pair;
  for (size_t r = 0; r < robot_.size(); ++r) {
    for (size_t o = 0; o < obstacles_.size(); ++o) {
      if (pairDistance(r, o, pose, bound, placed, pair)) {
        bound = pair.value;
        best = pair;
      } else {
        smallest_lower_bound = std::min(smallest_lower_bound, pair.value);
      }
    }
  }
  // Nothing below the cutoff: every pair was bounded below by at least the cutoff (+inf when
  // there is nothing to collide with).
  if (!best.exact) best.value = smallest_lower_bound;
  return best;
}

int CollisionWorld::closePairs(const JointVector& q, double cutoff, std::span<SignedDistance> out) const {
  const ChainPose pose = poseAt(q);
  PlacedPolygon placed;
  int count = 0;
  for (size_t r = 0; r < robot_.size(); ++r) {
    for (size_t o = 0; o < obstacles_.size(); ++o) {
      if (count == static_cast<int>(out.size())) return count;
      if (pairDistance(r, o, pose, cutoff, placed, out[static_cast<size_t>(count)])) ++count;
    }
  }
  return count;
}

}  // namespace cyber::planner

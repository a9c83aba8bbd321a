#include "cyber/planner/collision_world.hpp"

#include <algorithm>
#include <cmath>

#include "cyber/planner/signed_distance.hpp"

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

}  // namespace

CollisionWorld::CollisionWorld(const RobotModel& model, const Scene& scene, HeldPieces pieces)
    : pieces_(pieces), rail_base_m_(model.rail.base_m), rail_direction_(railDirection(model.rail)) {
  auto add_robot = [&](const std::vector<ConvexPolygon>& polygons) {
    for (const ConvexPolygon& polygon : polygons) {
      if (polygon.empty()) continue;
      RobotPart part;
      part.vertices = polygon.vertices();
      part.normals = outwardNormals(part.vertices);
      for (const Point2& v : part.vertices) part.centre += v;
      part.centre /= static_cast<double>(part.vertices.size());
      for (const Point2& v : part.vertices) {
        part.radius = std::max(part.radius, (v - part.centre).norm());
        reach_m_ = std::max(reach_m_, v.norm());
      }
      robot_.push_back(std::move(part));
    }
  };
  add_robot(model.geometry.arm);
  if (pieces.coral) add_robot(model.geometry.coral);
  if (pieces.algae) add_robot(model.geometry.algae);

  for (const NamedPolygon& named : scene.obstacles) {
    if (named.polygon.empty()) continue;
    Obstacle obstacle;
    obstacle.vertices = named.polygon.vertices();
    obstacle.normals = outwardNormals(obstacle.vertices);
    obstacle.box_min = obstacle.box_max = obstacle.vertices.front();
    for (const Point2& v : obstacle.vertices) {
      obstacle.box_min = obstacle.box_min.cwiseMin(v);
      obstacle.box_max = obstacle.box_max.cwiseMax(v);
    }
    obstacles_.push_back(std::move(obstacle));
  }
}

bool CollisionWorld::pairDistance(size_t r, size_t o, const ArmPose& pose, double bound, PlacedPolygon& placed,
                                  SignedDistance& out) const {
  const RobotPart& part = robot_[r];
  const Obstacle& obstacle = obstacles_[o];
  const int n = static_cast<int>(part.vertices.size());
  // Circle against box bounds the distance of separated shapes only, so it prunes only when
  // positive (a penetration can be deeper than the circle's radius).
  const double circle_bound =
      pointBoxDistance(pose.toWorld(part.centre), obstacle.box_min, obstacle.box_max) - part.radius;
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
        placed.vertices[i] = pose.toWorld(part.vertices[static_cast<size_t>(i)]);
        placed.normals[i] = pose.rotate(part.normals[static_cast<size_t>(i)]);
      }
      placed.placed_part = static_cast<int>(r);
    }
    pair = signedDistance(WorldPolygonView{placed.vertices, placed.normals, n}, obstacle_view, bound);
  } else {
    pair = signedDistance(ArmPolygonView{part.vertices.data(), part.normals.data(), n, &pose}, obstacle_view, bound);
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
  out.gradient = -(pose.pointJacobian(pair.witness_a).transpose() * pair.normal);
  return true;
}

SignedDistance CollisionWorld::distance(const JointVector& q, double cutoff) const {
  SignedDistance best;
  const ArmPose pose = poseAt(q);
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
  const ArmPose pose = poseAt(q);
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

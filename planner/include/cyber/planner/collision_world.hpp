#pragma once
// The robot polygons (every link's, and the held game pieces') for one set of held pieces against
// one scene's obstacles at one offset of its field elements:
// the signed distance d(q) of algorithm.md section 1 with its gradient dd/dq.

#include <limits>
#include <span>
#include <vector>

#include "cyber/planner/chain.hpp"
#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

/// The signed distance d(q) of the robot to the scene and its gradient (algorithm.md section 1).
struct SignedDistance {
  /// d(q) when it is below the cutoff asked for; otherwise only a lower bound >= the cutoff
  /// (exact == false, gradient zero). +inf when the scene has no obstacles.
  double value = std::numeric_limits<double>::infinity();
  JointVector gradient;  ///< dd/dq (joint units), one entry per joint
  bool exact = false;
  Point2 witness_robot = Point2::Zero();  ///< closest (or deepest) points, world frame
  Point2 witness_obstacle = Point2::Zero();
  int robot_polygon = -1;  ///< index into robotPolygons()
  int obstacle = -1;       ///< index into the scene's obstacles
};

/// The robot (with its held pieces) against one scene at one offset: distances and their gradients.
class CollisionWorld {
 public:
  /// Robot polygons: every link's, plus those of the held pieces (a held piece only adds geometry).
  /// The scene's field elements are shifted by scene_offset_m in x, its fixed obstacles are not.
  CollisionWorld(const RobotModel& model, const Scene& scene, HeldPieces pieces, double scene_offset_m = 0.0);
  /// The field elements swept over every offset of `band` (ConvexPolygon::sweptAlongX): a world no
  /// closer to the robot than the scene at any of those offsets (the grids of a band of offsets,
  /// docs/algorithm.md section 2, "Scene offsets").
  CollisionWorld(const RobotModel& model, const Scene& scene, HeldPieces pieces, const JointRange& band);

  /// Signed distance of the pose q: minimum over robot polygon x obstacle pairs. Pairs whose cheap
  /// lower bound (bounding circle against bounding box, then the separating-axis gap) cannot beat
  /// the best so far, or is already >= cutoff, are skipped; the result is exact whenever
  /// d(q) < cutoff. Allocation-free.
  [[nodiscard]] SignedDistance distance(const JointVector& q,
                                        double cutoff = std::numeric_limits<double>::infinity()) const;

  /// Every robot polygon x obstacle pair with signed distance below cutoff, each with its own
  /// gradient (at most out.size() of them; returns how many were written). Unlike distance(), a
  /// sum over these is smooth where the closest pair switches.
  int closePairs(const JointVector& q, double cutoff, std::span<SignedDistance> out) const;

  /// Upper bound of |d(q + dq) - d(q)| per unit of the given joint displacement magnitudes: no
  /// robot point moves faster than sum_j speed_j |dq_j|, with speed_j 1 for a prismatic joint and
  /// the largest distance of a point moved by a revolute joint from its axis, over the whole range
  /// of the joint after it (docs/algorithm.md section 1).
  [[nodiscard]] double lipschitzBound(const JointVector& abs_dq) const { return point_speed_.dot(abs_dq); }
  [[nodiscard]] const JointVector& pointSpeedBound() const { return point_speed_; }

  [[nodiscard]] HeldPieces pieces() const { return pieces_; }
  [[nodiscard]] int robotPolygonCount() const { return static_cast<int>(robot_.size()); }
  [[nodiscard]] int obstacleCount() const { return static_cast<int>(obstacles_.size()); }
  [[nodiscard]] ChainPose poseAt(const JointVector& q) const { return chainPose(chain_, q); }

 private:
  struct RobotPart {  ///< in its link's frame
    int link = 0;
    std::vector<Point2> vertices;
    std::vector<Point2> normals;
    Point2 centre = Point2::Zero();  ///< bounding circle
    double radius = 0.0;
  };
  struct Obstacle {  ///< world frame
    std::vector<Point2> vertices;
    std::vector<Point2> normals;
    Point2 box_min = Point2::Zero();
    Point2 box_max = Point2::Zero();
  };

  /// The robot polygons placed in the world once per query when small enough for this buffer (the
  /// usual case); larger ones are transformed on the fly.
  static constexpr int kStackVertices = 16;
  struct PlacedPolygon {
    Point2 vertices[kStackVertices];
    Point2 normals[kStackVertices];
    int placed_part = -1;
  };
  /// Signed distance of robot part r and obstacle o, or a lower bound >= bound (exact == false).
  [[nodiscard]] bool pairDistance(size_t r, size_t o, const ChainPose& pose, double bound, PlacedPolygon& placed,
                                  SignedDistance& out) const;

  HeldPieces pieces_;
  JointChain chain_;
  std::vector<RobotPart> robot_;
  std::vector<Obstacle> obstacles_;
  JointVector point_speed_;
};

}  // namespace cyber::planner

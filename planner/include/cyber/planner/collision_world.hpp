#pragma once
// The robot polygons for one set of held game pieces against one scene's obstacles:
// the signed distance d(q) of algorithm.md section 1 with its gradient dd/dq.

#include <limits>
#include <span>
#include <vector>

#include "cyber/planner/pose_transform.hpp"
#include "cyber/planner/robot_model.hpp"
#include "cyber/planner/types.hpp"

namespace cyber::planner {

struct SignedDistance {
  // d(q) when it is below the cutoff asked for; otherwise only a lower bound >= the cutoff
  // (exact == false, gradient zero). +inf when the scene has no obstacles.
  double value = std::numeric_limits<double>::infinity();
  JointVector gradient = JointVector::Zero();  // dd/dq (t in m, theta in rad)
  bool exact = false;
  Point2 witness_robot = Point2::Zero();  // closest (or deepest) points, world frame
  Point2 witness_obstacle = Point2::Zero();
  int robot_polygon = -1;  // index into robotPolygons()
  int obstacle = -1;       // index into the scene's obstacles
};

class CollisionWorld {
 public:
  // Robot polygons: the arm, plus coral and/or algae when held (a held piece only adds geometry).
  CollisionWorld(const RobotModel& model, const Scene& scene, HeldPieces pieces);

  // Signed distance of the pose q: minimum over robot polygon x obstacle pairs. Pairs whose cheap
  // lower bound (bounding circle against bounding box, then the separating-axis gap) cannot beat
  // the best so far, or is already >= cutoff, are skipped; the result is exact whenever
  // d(q) < cutoff. Allocation-free.
  [[nodiscard]] SignedDistance distance(const JointVector& q,
                                        double cutoff = std::numeric_limits<double>::infinity()) const;

  // Every robot polygon x obstacle pair with signed distance below cutoff, each with its own
  // gradient (at most out.size() of them; returns how many were written). Unlike distance(), a
  // sum over these is smooth where the closest pair switches.
  int closePairs(const JointVector& q, double cutoff, std::span<SignedDistance> out) const;

  // Largest distance of any robot point from the pivot [m]. Moving from q by dq moves every robot
  // point by at most |dt| + reach * |dtheta|, so d is Lipschitz with these constants.
  [[nodiscard]] double reach_m() const { return reach_m_; }
  // Upper bound of |d(q + dq) - d(q)| per unit of the given joint displacement magnitudes.
  [[nodiscard]] double lipschitzBound(const JointVector& abs_dq) const {
    return abs_dq[kElevator] + reach_m_ * abs_dq[kArm];
  }

  [[nodiscard]] HeldPieces pieces() const { return pieces_; }
  [[nodiscard]] int robotPolygonCount() const { return static_cast<int>(robot_.size()); }
  [[nodiscard]] int obstacleCount() const { return static_cast<int>(obstacles_.size()); }
  [[nodiscard]] ArmPose poseAt(const JointVector& q) const { return armPose(rail_base_m_, rail_direction_, q); }

 private:
  struct RobotPart {  // arm frame
    std::vector<Point2> vertices;
    std::vector<Point2> normals;
    Point2 centre = Point2::Zero();  // bounding circle
    double radius = 0.0;
  };
  struct Obstacle {  // world frame
    std::vector<Point2> vertices;
    std::vector<Point2> normals;
    Point2 box_min = Point2::Zero();
    Point2 box_max = Point2::Zero();
  };

  // The arm polygons placed in the world once per query when small enough for this buffer (the
  // usual case); larger ones are transformed on the fly.
  static constexpr int kStackVertices = 16;
  struct PlacedPolygon {
    Point2 vertices[kStackVertices];
    Point2 normals[kStackVertices];
    int placed_part = -1;
  };
  // Signed distance of robot part r and obstacle o, or a lower bound >= bound (exact == false).
  [[nodiscard]] bool pairDistance(size_t r, size_t o, const ArmPose& pose, double bound, PlacedPolygon& placed,
                                  SignedDistance& out) const;

  HeldPieces pieces_;
  Point2 rail_base_m_ = Point2::Zero();
  Point2 rail_direction_ = Point2(1.0, 0.0);
  std::vector<RobotPart> robot_;
  std::vector<Obstacle> obstacles_;
  double reach_m_ = 0.0;
};

}  // namespace cyber::planner

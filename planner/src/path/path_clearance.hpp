#pragma once
// Continuous clearance checks of a straight segment or a spline path against a collision world.
//
// Steps are certified by the Lipschitz bound of d (CollisionWorld::lipschitzBound): from a sample
// with d >= clearance + margin the next sample may be as far as the motion that can lose at most
// the margin. Where the margin is small the step never shrinks below the dense spacing
// (max |dq_j| <= max_step, 1 mm or 1 mrad by default), so the check is at least as strict as
// sampling at that spacing, and continuous wherever the margin allows.

#include <limits>

#include "cyber/planner/collision_world.hpp"
#include "cyber/planner/robot_model.hpp"
#include "path/cubic_spline_path.hpp"

namespace cyber::planner {

struct ClearanceCheck {
  bool clear = true;          // d >= clearance along the whole segment or path
  bool within_limits = true;  // the path stays inside the joint limits (exact, per segment)
  double min_distance_m = std::numeric_limits<double>::infinity();  // smallest d sampled
  double at_s = 0.0;    // where that was (path parameter, or fraction of the segment)
  int evaluations = 0;  // distance evaluations spent

  [[nodiscard]] bool ok() const { return clear && within_limits; }
};

inline constexpr double kDenseCheckStep = 1e-3;  // m or rad

// Straight segment a -> b. Stops at the first sample closer than the clearance.
ClearanceCheck checkSegment(const CollisionWorld& world, const JointVector& a, const JointVector& b, double clearance_m,
                            double max_step = kDenseCheckStep);

// A straight step a -> b whose ends' distances are known (exact, or lower bounds: the C-space
// grid's steps between free nodes). Each part is cleared by the cones of its ends' distances, or
// halved with a new distance at its middle down to the dense spacing, so the check is at least as
// strict as sampling at that spacing (docs/algorithm.md 2.1).
// Along a straight step whose ends are distance_a_m and distance_b_m from the obstacles, and whose
// motion can change the distance by at most bound_m, the distance is at least the larger of the two
// ends' cones, lowest where they meet: (a + b - bound) / 2. True when that keeps the clearance.
inline bool endsClearStep(double distance_a_m, double distance_b_m, double bound_m, double clearance_m) {
  return 0.5 * (distance_a_m + distance_b_m - bound_m) >= clearance_m;
}

struct StepCheck {
  bool clear = true;    // no sample closer than the clearance
  int evaluations = 0;  // distances asked for: 0 when the ends' cones clear the whole step
};
StepCheck checkStep(const CollisionWorld& world, const JointVector& a, const JointVector& b, double clearance_m,
                    double distance_a_m, double distance_b_m, double max_step = kDenseCheckStep);

// The whole spline path, and its exact joint range against the model's limits. Stops at the first
// violation; on success the minimum is refined by a dense scan around the closest sample.
ClearanceCheck checkPath(const CubicSplinePath& path, const CollisionWorld& world, const RobotModel& model,
                         double clearance_m, double max_step = kDenseCheckStep);

}  // namespace cyber::planner

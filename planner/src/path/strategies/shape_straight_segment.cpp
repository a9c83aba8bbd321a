// The straight segment to the goal, bent for time (docs/algorithm.md section 2.6).
#include "path/strategies/path_strategies.hpp"

#include "math/weighted_norm.hpp"
#include "path/path_optimizer.hpp"
#include "path/path_shaping.hpp"

namespace cyber::planner {
namespace {

// A direct path, bent by the shape search from knots spread evenly along it; only when the
// segment is estimated slower than its slower joint moving alone (otherwise that joint's limits
// bind all along and no shape can be faster).
void shapeStraightSegment(const CandidateInputs& in, CandidateList& list) {
  if (!in.direct || list.empty()) return;
  const PathStrategySettings& s = in.settings();
  const JointVector& metric = in.model.planner.metric;
  if (!(straightEstimate(in.from(), in.goal, in.drives, metric, s.gate_grid_points) >
        s.direct_shape_ratio * slowerJointAlone(in.from(), in.goal, in.drives, metric, s.gate_grid_points))) {
    return;
  }
  const std::vector<JointVector> tail(in.polyline.begin() + in.fixed_head - 1, in.polyline.end());
  std::vector<JointVector> knots(in.polyline.begin(), in.polyline.begin() + in.fixed_head - 1);
  const double tail_length = weightedNorm(tail.back() - tail.front(), metric);
  const std::vector<JointVector> spread = resamplePolyline(tail, metric, tail_length / (s.direct_shape_knots - 1));
  knots.insert(knots.end(), spread.begin(), spread.end());
  const PlannedPath straight = list.front();
  addShaped(in, list, straight, knots);
}

}  // namespace

CYBER_PATH_STRATEGY(shape_straight_segment, "shape the straight segment", 10, shapeStraightSegment,
                    "a straight segment is not the fastest path when the joints' limits differ (gravity, voltage)");

}  // namespace cyber::planner

// Both joints' own fastest motions side by side (docs/algorithm.md section 2.6).
#include "path/strategies/path_strategies.hpp"

#include "path/synchronised_path.hpp"
#include "timing/path_timing.hpp"

namespace cyber::planner {
namespace {

// From rest, the joints' own fastest motions side by side (synchronised_path.hpp), inside a window
// of the fastest candidate's estimate over the slower joint alone. That coarser estimate first:
// the joints' own profiles cost five times as much, and half the public moves are already within
// a per cent of it.
void synchroniseJoints(const CandidateInputs& in, CandidateList& list) {
  if (list.empty() || !(in.start_velocity.array() == 0.0).all()) return;
  const PathStrategySettings& s = in.settings();
  const PlannedPath fastest = list.front();
  const double fastest_s = estimateDuration(*fastest.path, in.drives, 0.0, s.check_grid_points);
  const double slower_alone_s =
      slowerJointAlone(in.start, in.goal, in.drives, in.model.planner.metric, s.timing_grid_points);
  if (!(fastest_s > s.synchronised_ratio * slower_alone_s && fastest_s < s.synchronised_max_ratio * slower_alone_s)) {
    return;
  }
  if (auto synchronised = synchronisedPath(in.start, in.goal, in.world, in.model, fastest_s / s.synchronised_ratio,
                                           in.model.planner.synchronised)) {
    putFirstIfFaster(in, list, fastest, fastest_s, std::move(synchronised->path), std::move(synchronised->waypoints),
                     synchronised->min_clearance_m, PlanMethod::Smoothing::kSynchronised);
  }
}

}  // namespace

CYBER_PATH_STRATEGY(synchronise_joints, "synchronise the joints", 50, synchroniseJoints,
                    "from rest, many moves are as fast as their slower joint alone; the search's paths lose 3-5 %");

}  // namespace cyber::planner

// The fastest candidate's shape searched against its time (docs/algorithm.md section 2.6).
#include "path/strategies/path_strategies.hpp"

namespace cyber::planner {
namespace {

// The fastest searched candidate's shape searched against its estimated time, when it is
// estimated well above the straight segment.
void shapeFastestPath(const CandidateInputs& in, CandidateList& list) {
  if (in.direct || list.empty()) return;
  if (!(list.estimate(in, 0) > in.settings().shape_ratio * in.straight_estimate_s)) return;
  const PlannedPath fastest = list.front();
  addShaped(in, list, fastest, fastest.waypoints);
}

}  // namespace

CYBER_PATH_STRATEGY(shape_fastest_path, "shape the fastest path", 40, shapeFastestPath,
                    "the fastest path keeps to the middle of the free space; time may not");

}  // namespace cyber::planner

// The search's path with its runs of nodes cut short (docs/algorithm.md section 2.6).
#include "path/strategies/path_strategies.hpp"

namespace cyber::planner {
namespace {

// The search's polyline with every run of nodes that one clear straight segment can replace
// replaced by it (docs/performance.md, "Choosing the path for time").
void shortcutSearchPath(const CandidateInputs& in, CandidateList& list) {
  if (in.direct) return;
  const std::vector<JointVector> shortcut =
      shortcutPolyline(in.world, in.polyline, in.fixed_head, shortcutClearance(in));
  if (shortcut.size() < in.polyline.size()) addSmoothed(in, list, shortcut);
}

}  // namespace

CYBER_PATH_STRATEGY(shortcut_search_path, "shortcut", 20, shortcutSearchPath,
                    "the search's grid and potential bend the path; time favours straight segments");

}  // namespace cyber::planner

#pragma once
// How long each stage of one plan took (docs/algorithm.md sections 2 and 3 name the stages). Its own
// header so the daemon reports the same type without pulling in the whole planner.

namespace cyber::planner {

struct StageTimesMs {
  double grid = 0.0;    // building the grid of this scene and piece set, once at create()
  double search = 0.0;  // this request: grid search (or the direct check)
  double smooth = 0.0;  // this request: optimisation, spline, clearance check
  double topp = 0.0;    // this request: time-optimal parameterisation and its limit check
  double total = 0.0;   // this request, end to end (excludes the one-off grid build)
};

}  // namespace cyber::planner

#pragma once
// Where a path folds back on itself: its tangent turns by more than a right angle between two
// points a short distance apart. The mechanism must come to rest at such a fold (its velocity
// reverses), so a path that leaves along a start velocity and then folds is a stop in disguise,
// and TOPP's solver converges badly on it (docs/moving-starts.md, candidate 1).

#include "cyber/planner/types.hpp"

namespace cyber::planner {

// The smallest cosine between the tangents q'(s) and q'(s + spacing) over the path, on samples
// `spacing` apart (s in path units; the last sample is the path's end): 1 on a straight path,
// -1 where it reverses. A zero-length path, or a tangent of zero length, counts as straight.
[[nodiscard]] double sharpestTurnCosine(const GeometricPath& path, double spacing);

}  // namespace cyber::planner

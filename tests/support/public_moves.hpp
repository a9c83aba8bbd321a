#pragma once
// The public benchmark moves: every ordered pair of named poses within one game-piece set of
// shared/reference/poses.json (copied here: the project never reads ../shared).

#include <string>
#include <vector>

#include "cyber/planner/types.hpp"

namespace cyber::test {

struct NamedPose {
  std::string name;
  planner::JointVector q;
};

struct PublicMove {
  std::string label;  // e.g. "none:STOW->L4"
  planner::HeldPieces pieces;
  planner::JointVector from;
  planner::JointVector to;
};

// Poses of one game-piece set ("none", "coral", "algae").
const std::vector<NamedPose>& publicPoses(const std::string& piece_set);
// All 144 ordered pairs.
const std::vector<PublicMove>& publicMoves();
// The move with this label; throws std::out_of_range when there is none.
const PublicMove& publicMove(const std::string& label);

}  // namespace cyber::test

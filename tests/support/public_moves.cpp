#include "public_moves.hpp"

#include "reference_model.hpp"

#include <map>
#include <stdexcept>

namespace cyber::test {
namespace {

using planner::JointVector;

const std::map<std::string, std::vector<NamedPose>>& table() {
  static const std::map<std::string, std::vector<NamedPose>> poses = {
      {"none",
       {{"STOW", JointVector{{0.20, 1.57}}},
        {"INTAKE", JointVector{{0.58, 2.97}}},
        {"L1", JointVector{{0.49, 6.07}}},
        {"L2", JointVector{{0.73, 6.07}}},
        {"L3", JointVector{{1.22, 5.69}}},
        {"L4", JointVector{{1.97, 5.17}}},
        {"ALGAE_LOW", JointVector{{0.71, 0.10}}},
        {"ALGAE_HIGH", JointVector{{1.17, 0.10}}},
        {"NET", JointVector{{1.93, 1.71}}},
        {"PROCESSOR", JointVector{{0.16, 0.10}}}}},
      {"coral",
       {{"STOW", JointVector{{0.20, 1.57}}},
        {"INTAKE", JointVector{{0.58, 2.97}}},
        {"L1", JointVector{{0.62, 5.73}}},
        {"L2", JointVector{{0.78, 6.09}}},
        {"L3", JointVector{{1.27, 5.79}}},
        {"L4", JointVector{{1.98, 5.39}}},
        {"NET", JointVector{{1.93, 1.71}}}}},
      {"algae",
       {{"STOW", JointVector{{0.20, 1.57}}},
        {"INTAKE", JointVector{{0.58, 2.97}}},
        {"NET", JointVector{{1.93, 1.71}}},
        {"HOLD_HIGH", JointVector{{1.98, 5.69}}}}},
  };
  return poses;
}

}  // namespace

const std::vector<NamedPose>& publicPoses(const std::string& piece_set) { return table().at(piece_set); }

const std::vector<PublicMove>& publicMoves() {
  static const std::vector<PublicMove> moves = [] {
    std::vector<PublicMove> out;
    for (const char* set : {"none", "coral", "algae"}) {
      const planner::HeldPieces pieces = referencePieces(set);
      for (const NamedPose& a : publicPoses(set)) {
        for (const NamedPose& b : publicPoses(set)) {
          if (a.name == b.name) continue;
          out.push_back({std::string(set) + ":" + a.name + "->" + b.name, pieces, a.q, b.q});
        }
      }
    }
    return out;
  }();
  return moves;
}

const PublicMove& publicMove(const std::string& label) {
  for (const PublicMove& move : publicMoves()) {
    if (move.label == label) return move;
  }
  throw std::out_of_range("no public move " + label);
}

}  // namespace cyber::test

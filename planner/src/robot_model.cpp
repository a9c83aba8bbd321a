#include "cyber/planner/robot_model.hpp"

namespace cyber::planner {
namespace {

template <class Named>
int indexByName(const std::vector<Named>& items, const std::string& name) {
  for (size_t i = 0; i < items.size(); ++i) {
    if (items[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace

int RobotModel::sceneIndex(const std::string& scene_name) const { return indexByName(scenes, scene_name); }
int RobotModel::pieceIndex(const std::string& piece_name) const { return indexByName(pieces, piece_name); }
int RobotModel::jointIndex(const std::string& joint_name) const {
  for (int j = 0; j < kJointCount; ++j) {
    if (joints[static_cast<size_t>(j)].name == joint_name) return j;
  }
  return -1;
}

std::string RobotModel::pieceSetName(HeldPieces held) const {
  std::string out;
  for (size_t i = 0; i < pieces.size(); ++i) {
    if (!held.holds(static_cast<int>(i))) continue;
    if (!out.empty()) out += '+';
    out += pieces[i].name;
  }
  return out.empty() ? "none" : out;
}

}  // namespace cyber::planner

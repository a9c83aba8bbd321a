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
  for (int j = 0; j < jointCount(); ++j) {
    if (joints[j].name == joint_name) return j;
  }
  return -1;
}

DriveModel RobotModel::driveModel(HeldPieces held) const {
  if (drive_kind == DriveKind::kFeedforward) return DriveModel(joints, drives);
  PerJoint<LinkInertia> moving = bodies;
  for (size_t i = 0; i < pieces.size() && i < piece_inertias.size(); ++i) {
    if (!held.holds(static_cast<int>(i))) continue;
    LinkInertia& body = moving[pieces[i].joint];
    body = combine(body, piece_inertias[i]);
  }
  return DriveModel(drives, ChainDynamics(joints, moving));
}

Result<HeldPieces> RobotModel::piecesNamed(std::string_view names) const {
  HeldPieces held;
  if (names.empty() || names == "none") return held;
  while (true) {
    const size_t end = names.find_first_of(",+");
    const std::string name(names.substr(0, end));
    const int piece = pieceIndex(name);
    if (piece < 0) {
      std::string known;
      for (const GamePiece& p : pieces) known += (known.empty() ? "" : ", ") + p.name;
      return PlanError{PlanStatus::kInvalidInput,
                       "unknown game piece \"" + name + "\" (this robot's: " + (known.empty() ? "none" : known) + ")"};
    }
    held = held.with(piece);
    if (end == std::string_view::npos) return held;
    names.remove_prefix(end + 1);
  }
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

#include "read_chain.hpp"

#include <fmt/format.h>

#include <algorithm>

#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <string>

#include "read_drives.hpp"

namespace cyber::config::detail {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

// A joint named by a link or a piece: its name in [[joints]].
int jointOf(TableReader& table, const planner::RobotModel& robot) {
  std::string names;
  for (int j = 0; j < robot.jointCount(); ++j) {
    names += (j == 0 ? "\"" : (j + 1 == robot.jointCount() ? "\" or \"" : "\", \"")) + robot.joints[j].name;
  }
  names += "\"";
  const std::string name = table.string("joint", "a joint's name as a string, " + names);
  const int joint = robot.jointIndex(name);
  if (joint < 0) table.fail("joint", "unknown joint \"" + name + "\" (expected " + names + ")");
  return joint;
}

// Joint, scene and piece names travel in LCM strings, which end at the first NUL, and in log
// lines (docs/lcm.md): a name is non-empty and has no control characters.
void checkName(TableReader& table, const std::string& key, const std::string& name) {
  if (name.empty()) table.fail(key, "must not be empty");
  const bool control = std::any_of(name.begin(), name.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte < 0x20 || byte == 0x7f;
  });
  if (control) table.fail(key, "a name may not contain control characters (it is sent in LCM messages)");
}

planner::JointType jointType(TableReader& joint) {
  const std::string type = joint.string("type");
  if (type == "prismatic") return planner::JointType::kPrismatic;
  if (type == "revolute") return planner::JointType::kRevolute;
  joint.fail("type", "expected \"prismatic\" or \"revolute\", got \"" + type + "\"");
}

}  // namespace

void rejectOldFormat(const TableReader& root) {
  if (root.has("robot") || (root.has("joints") && !root.isArray("joints"))) {
    root.fail("joints",
              "this is the format before joint chains: describe the mechanism as two [[joints]] entries (name, type "
              "= \"prismatic\" | \"revolute\", min, max, origin_m, axis_deg), its outlines as [links.NAME] (joint, "
              "polygons) and its game pieces as [pieces.NAME] (joint, polygons); drives are keyed by joint name; "
              "see docs/configuration.md");
  }
}

void readJoints(TableReader& root, planner::RobotModel& robot) {
  const toml::array& joints = root.array("joints");
  if (joints.empty() || joints.size() > static_cast<size_t>(planner::kMaxJoints)) {
    root.fail("joints",
              fmt::format("expected one to {} joints, in chain order (got {})", planner::kMaxJoints, joints.size()));
  }
  robot.joints = planner::JointChain(static_cast<int>(joints.size()));
  for (size_t i = 0; i < joints.size(); ++i) {
    TableReader joint = tableAt(joints[i], "joints[" + std::to_string(i) + "]");
    planner::ChainJoint& out = robot.joints[i];
    out.name = joint.string("name");
    checkName(joint, "name", out.name);
    for (size_t k = 0; k < i; ++k) {
      if (out.name == robot.joints[k].name) joint.fail("name", "each joint needs its own name");
    }
    out.type = jointType(joint);
    out.range.min = joint.number("min");
    out.range.max = joint.number("max", Bounds{out.range.min, 1e300, true});
    if (out.type == planner::JointType::kRevolute && out.range.max - out.range.min > 2.0 * std::numbers::pi + 1e-9) {
      joint.fail("max", "a revolute joint may span at most one turn (no wrap-around)");
    }
    out.origin_m = joint.vector2("origin_m");
    out.axis_rad = joint.number("axis_deg", Bounds{-360.0, 360.0}) * kDegToRad;
    joint.finish();
  }
}

void readLinks(TableReader links, planner::RobotModel& robot) {
  for (const std::string& name : links.keys()) {
    TableReader link = links.table(name);
    planner::LinkGeometry out;
    out.name = name;
    out.joint = jointOf(link, robot);
    out.polygons = link.polygons("polygons");
    link.finish();
    robot.links.push_back(std::move(out));
  }
  if (robot.links.empty()) links.fail("", "define at least one link outline");
}

void readPieces(TableReader pieces, planner::RobotModel& robot) {
  for (const std::string& name : pieces.keys()) {
    checkName(pieces, name, name);
    if (name.find('+') != std::string::npos || name == "none") {
      pieces.fail(name, "a piece name may not be \"none\" or contain '+' (they name held sets)");
    }
    TableReader piece = pieces.table(name);
    planner::GamePiece out;
    out.name = name;
    out.joint = jointOf(piece, robot);
    out.polygons = piece.polygons("polygons");
    // Mass data count under rigid-body drives; the cg defaults to the mean of the vertices.
    planner::LinkInertia inertia;
    if (piece.has("mass_kg")) {
      planner::Point2 mean = planner::Point2::Zero();
      int count = 0;
      for (const planner::ConvexPolygon& p : out.polygons) {
        for (const planner::Point2& v : p.vertices()) {
          mean += v;
          ++count;
        }
      }
      inertia = readInertia(piece, mean / std::max(count, 1));
    }
    piece.finish();
    robot.pieces.push_back(std::move(out));
    robot.piece_inertias.push_back(inertia);
  }
  if (static_cast<int>(robot.pieces.size()) > planner::HeldPieces::kMaxPieces) {
    pieces.fail("", "at most " + std::to_string(planner::HeldPieces::kMaxPieces) +
                        " game pieces (every held set gets its own grids at start-up)");
  }
}

void readScenes(TableReader& root, TableReader obstacle_table, planner::RobotModel& robot) {
  std::map<std::string, planner::ConvexPolygon> obstacles;
  for (const std::string& name : obstacle_table.keys()) obstacles.emplace(name, obstacle_table.polygon(name));
  obstacle_table.finish();

  const toml::array& scenes = root.array("scenes");
  if (scenes.empty()) root.fail("scenes", "expected at least one scene");
  for (size_t i = 0; i < scenes.size(); ++i) {
    TableReader scene = tableAt(scenes[i], "scenes[" + std::to_string(i) + "]");
    planner::Scene out;
    out.name = scene.string("name");
    checkName(scene, "name", out.name);
    if (robot.sceneIndex(out.name) >= 0) scene.fail("name", "duplicate scene name \"" + out.name + "\"");
    auto named = [&](const char* key, std::vector<planner::NamedPolygon>& into) {
      if (!scene.has(key)) return;
      for (const std::string& name : scene.strings(key, "an obstacle's name as a string, a key of [obstacles]")) {
        const auto it = obstacles.find(name);
        if (it == obstacles.end()) scene.fail(key, "unknown obstacle \"" + name + "\"");
        into.push_back({name, it->second});
      }
    };
    named("obstacles", out.obstacles);
    named("fixed", out.fixed);
    if (out.obstacles.empty() && out.fixed.empty()) scene.fail("obstacles", "a scene needs at least one obstacle");
    if (scene.has("offset_range_m")) {
      const Eigen::Vector2d range = scene.vector2("offset_range_m", Bounds{-5.0, 5.0});
      if (!(range.x() <= 0.0 && 0.0 <= range.y())) {
        scene.fail("offset_range_m", "[min, max] with min <= 0 <= max (0 is the scene as drawn)");
      }
      out.offset_range_m = planner::JointRange{range.x(), range.y()};
    }
    scene.finish();
    robot.scenes.push_back(std::move(out));
  }
}

std::vector<PoseSet> readPoses(TableReader t, const planner::RobotModel& robot) {
  std::vector<PoseSet> sets;
  for (const std::string& name : t.keysInFileOrder()) {
    TableReader set = t.table(name);
    const auto held = robot.piecesNamed(name);
    if (!held) t.fail(name, held.error().message + "; a set is \"none\" or piece names joined by '+'");
    PoseSet out{name, held.value(), {}};
    for (const std::string& pose : set.keysInFileOrder()) {
      const planner::JointVector q = set.jointVector(pose, robot.jointCount());
      if (!robot.withinLimits(q)) set.fail(pose, "outside the joint ranges");
      out.poses.push_back(NamedPose{pose, q});
    }
    set.finish();
    sets.push_back(std::move(out));
  }
  t.finish();
  return sets;
}

}  // namespace cyber::config::detail

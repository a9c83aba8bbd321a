// The grid cache's key: FNV-1a as defined, the same for the same inputs, and changed by every
// input CSpaceGrid::build reads (a stale cache is never trusted); names do not change it. The
// reference grids are pinned to kGridFormatVersion, so a change of how grids are built fails here
// until the version is bumped.

#include "path/grid_cache_key.hpp"

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "path/cspace_grid.hpp"
#include "reference_model.hpp"

namespace cyber::planner {
namespace {

std::uint64_t fnv(std::string_view text) {
  Fnv1a64 hash;
  for (const char c : text) {
    const auto byte = static_cast<std::uint8_t>(c);
    hash.bytes(std::span(&byte, 1));
  }
  return hash.value();
}

TEST(GridCacheKey, Fnv1aGivesTheValuesOfItsDefinition) {
  EXPECT_EQ(fnv(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(fnv("foobar"), 0x85944171f73967e8ULL);
}

std::uint64_t keyOf(const RobotModel& model, const JointRange& band = {}) {
  return gridCacheKey(model, model.scenes.front(), band);
}

TEST(GridCacheKey, IsTheSameForTheSameInputsAndNamesDoNotChangeIt) {
  RobotModel model = test::referenceModel();
  const std::uint64_t key = keyOf(model);
  EXPECT_EQ(keyOf(test::referenceModel()), key);
  model.name = "renamed";
  model.scenes.front().name = "renamed";
  model.joints[0].name = "renamed";
  EXPECT_EQ(keyOf(model), key);
  // Settings the grids do not read do not change it either.
  model.planner.topp.grid_points += 1;
  model.drives[0].kV += 1.0;
  EXPECT_EQ(keyOf(model), key);
}

TEST(GridCacheKey, EveryInputOfTheGridsChangesIt) {
  const RobotModel reference = test::referenceModel();
  const std::uint64_t key = keyOf(reference);
  const double nudge = 1e-9;  // far below any tolerance: the key compares bits
  const std::vector<std::pair<const char*, std::function<void(RobotModel&)>>> changes = {
      {"joint type", [](RobotModel& m) { m.joints[1].type = JointType::kPrismatic; }},
      {"joint origin", [&](RobotModel& m) { m.joints[1].origin_m.y() += nudge; }},
      {"joint axis", [&](RobotModel& m) { m.joints[0].axis_rad += nudge; }},
      {"joint range", [&](RobotModel& m) { m.joints[1].range.max -= nudge; }},
      {"link polygon",
       [&](RobotModel& m) {
         std::vector<Point2> v = m.links.front().polygons.front().vertices();
         v.front().x() += nudge;
         m.links.front().polygons.front() = ConvexPolygon::fromVertices(v).value();
       }},
      {"link joint", [](RobotModel& m) { m.links.front().joint = 1 - m.links.front().joint; }},
      {"piece polygon", [](RobotModel& m) { m.pieces.front().polygons.push_back(m.pieces.back().polygons.front()); }},
      {"a piece less", [](RobotModel& m) { m.pieces.pop_back(); }},
      {"obstacle", [](RobotModel& m) { m.scenes.front().obstacles.pop_back(); }},
      {"fixed obstacle", [](RobotModel& m) { m.scenes.front().fixed.push_back(m.scenes.front().obstacles.front()); }},
      {"offset range", [&](RobotModel& m) { m.scenes.front().offset_range_m.max += nudge; }},
      {"clearance", [&](RobotModel& m) { m.clearance_m += nudge; }},
      {"metric", [&](RobotModel& m) { m.planner.metric[1] += nudge; }},
      {"grid step", [&](RobotModel& m) { m.planner.grid.step[0] += nudge; }},
      {"joint limit margin", [&](RobotModel& m) { m.planner.grid.joint_limit_margin += nudge; }},
      {"potential weight", [&](RobotModel& m) { m.planner.search.potential_weight += nudge; }},
      {"potential range", [&](RobotModel& m) { m.planner.search.potential_range += nudge; }},
      {"band width", [&](RobotModel& m) { m.planner.search.offset_band_clearances += nudge; }},
  };
  for (const auto& [what, change] : changes) {
    RobotModel model = reference;
    change(model);
    EXPECT_NE(keyOf(model), key) << what;
  }
  EXPECT_NE(keyOf(reference, JointRange{0.0, 0.1}), key) << "band";
  EXPECT_NE(keyOf(reference, JointRange{0.0, 0.1}), keyOf(reference, JointRange{0.0, 0.1 + nudge})) << "band";
  EXPECT_NE(gridCacheKey(reference, reference.scenes.back(), {}), key) << "scene";
}

// The reference robot's grids of the scene as drawn, as a hash of their nodes and steps. When this
// fails, the grids a planner builds have changed: bump kGridFormatVersion (every cached grid is
// then rebuilt) and record the new version with the printed fingerprint. Only where the recorded
// value was measured (x86-64: arm64's fused multiply-adds may move a node, docs/operations.md,
// "arm64 coprocessors").
TEST(GridCacheKey, TheReferenceGridsAreThoseOfThisFormatVersion) {
#if !defined(__x86_64__)
  GTEST_SKIP() << "the fingerprint was recorded on x86-64";
#endif
  const RobotModel& model = test::referenceModel();
  Fnv1a64 hash;
  for (int set = 0; set < model.pieceSetCount(); ++set) {
    const CollisionWorld world(model, model.scenes.front(), HeldPieces::fromIndex(set));
    const CSpaceGrid grid = CSpaceGrid::build(world, model);
    hash.bytes(grid.packedNodes());
    hash.u64(static_cast<std::uint64_t>(grid.checkedStepCount()));
  }
  char fingerprint[32];
  std::snprintf(fingerprint, sizeof fingerprint, "%016llx", static_cast<unsigned long long>(hash.value()));
  EXPECT_EQ(kGridFormatVersion, 2U);
  EXPECT_EQ(std::string(fingerprint), "80c26705def97911")
      << "the reference grids changed: bump kGridFormatVersion (path/grid_cache_key.hpp) and record " << fingerprint;
}

}  // namespace
}  // namespace cyber::planner

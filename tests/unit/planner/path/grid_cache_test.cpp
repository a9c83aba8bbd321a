// The grid cache: grids read back are those that were written; every bad file (missing, empty,
// truncated, a flipped byte anywhere, another key or version, nodes no built grid has, a folder in
// its place) is refused with its reason and never crashes; a folder that cannot be written is no
// error; create() rebuilds and rewrites a corrupt file; and plans are bit for bit the same with
// the cache as without it.

#include "path/grid_cache.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cyber/planner/motion_planner.hpp"
#include "path/grid_cache_key.hpp"
#include "public_moves.hpp"
#include "reference_model.hpp"

namespace cyber::planner {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<char>;

const RobotModel& model() { return test::referenceModel(); }

// The reference robot's grids of its first scene as drawn, built once.
const PathPlanner& drawn() {
  static const PathPlanner planner(model(), model().scenes.front());
  return planner;
}

std::vector<CSpaceGrid> drawnGrids() {
  std::vector<CSpaceGrid> out;
  for (int set = 0; set < model().pieceSetCount(); ++set) out.push_back(drawn().grid(HeldPieces::fromIndex(set)));
  return out;
}

class GridCache : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "cyber-grid-cache-XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    file_ = gridCacheFile(dir_, model(), 0, 0, JointRange{});
  }
  void TearDown() override { fs::remove_all(dir_); }

  void writeDrawn() const { ASSERT_TRUE(writeGridCache(file_, drawnGrids()).ok()); }
  [[nodiscard]] Bytes bytes() const {
    std::ifstream in(file_.path, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), {});
  }
  void replaceWith(const Bytes& content) const {
    std::ofstream out(file_.path, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
  }
  [[nodiscard]] GridCacheStatus readStatus() const { return readGridCache(file_, model()).status(); }

  fs::path dir_;
  GridCacheFile file_;
};

void expectSameGrid(const CSpaceGrid& a, const CSpaceGrid& b) {
  ASSERT_EQ(a.cellCount(), b.cellCount());
  EXPECT_EQ(a.packedNodes(), b.packedNodes());
  EXPECT_EQ(a.checkedStepCount(), b.checkedStepCount());
  EXPECT_EQ(a.clearance_m(), b.clearance_m());
  EXPECT_EQ(a.potentialWeight(), b.potentialWeight());
  ASSERT_EQ(a.holes().size(), b.holes().size());
  for (size_t h = 0; h < a.holes().size(); ++h) {
    EXPECT_EQ(a.holes()[h].i, b.holes()[h].i);
    EXPECT_EQ(a.holes()[h].j, b.holes()[h].j);
    EXPECT_EQ(a.holes()[h].cells, b.holes()[h].cells);
  }
  int differing = 0;
  for (int c = 0; c < a.cellCount(); ++c) {
    const bool same = a.potential(c) == b.potential(c) && a.region(c) == b.region(c) && a.node(c) == b.node(c);
    differing += same ? 0 : 1;
  }
  EXPECT_EQ(differing, 0);
}

TEST_F(GridCache, GridsReadBackAreTheGridsWritten) {
  EXPECT_EQ(readStatus(), GridCacheStatus::kMissing);
  writeDrawn();
  const auto read = readGridCache(file_, model());
  ASSERT_TRUE(read.ok()) << static_cast<int>(read.status());
  ASSERT_EQ(static_cast<int>(read.value().size()), model().pieceSetCount());
  for (int set = 0; set < model().pieceSetCount(); ++set) {
    expectSameGrid(read.value()[static_cast<size_t>(set)], drawn().grid(HeldPieces::fromIndex(set)));
  }
  // Nothing but the file is left in the folder (the temporary file was renamed).
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}), 1);
}

TEST_F(GridCache, AnEmptyOrTruncatedFileIsCorrupt) {
  writeDrawn();
  const Bytes whole = bytes();
  for (const size_t size : {size_t{0}, size_t{7}, size_t{47}, size_t{48}, whole.size() / 2, whole.size() - 1}) {
    replaceWith(Bytes(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(size)));
    EXPECT_EQ(readStatus(), GridCacheStatus::kCorrupt) << size << " bytes";
  }
  Bytes longer = whole;
  longer.push_back(0);
  replaceWith(longer);
  EXPECT_EQ(readStatus(), GridCacheStatus::kCorrupt) << "a byte more";
}

TEST_F(GridCache, AFlippedByteAnywhereIsRefused) {
  writeDrawn();
  const Bytes whole = bytes();
  // Every byte of the header, then bytes spread over the payload (its checked-step counts too).
  std::vector<size_t> positions;
  for (size_t at = 0; at < 48; ++at) positions.push_back(at);
  for (size_t at = 48; at < whole.size(); at += 997) positions.push_back(at);
  positions.push_back(whole.size() - 1);
  for (const size_t at : positions) {
    Bytes flipped = whole;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    replaceWith(flipped);
    const GridCacheStatus status = readStatus();
    // The version (bytes 8 to 11) and key (16 to 23) name other inputs: stale; the rest is corrupt.
    const bool names_other_inputs = (at >= 8 && at < 12) || (at >= 16 && at < 24);
    EXPECT_EQ(status, names_other_inputs ? GridCacheStatus::kStale : GridCacheStatus::kCorrupt) << "byte " << at;
  }
}

TEST_F(GridCache, AFileOfOtherInputsIsStale) {
  writeDrawn();
  RobotModel closer = model();
  closer.clearance_m *= 2.0;
  EXPECT_EQ(readGridCache(gridCacheFile(dir_, closer, 0, 0, JointRange{}), closer).status(), GridCacheStatus::kStale);
  GridCacheFile band = file_;
  band.key = gridCacheKey(model(), model().scenes.front(), JointRange{0.0, 0.1});
  EXPECT_EQ(readGridCache(band, model()).status(), GridCacheStatus::kStale);
}

// A file whose checksum holds but whose nodes no build gives (a step into a blocked node, a bit no
// step has) is refused: what the search reads is always a grid build() could have made.
TEST_F(GridCache, NodesNoBuiltGridHasAreCorruptEvenWithTheirChecksum) {
  const CSpaceGrid& grid = drawn().grid(HeldPieces{});
  int blocked_neighbour = -1;  // a free node whose +second-joint neighbour is blocked
  for (int c = 0; c + 1 < grid.cellCount() && blocked_neighbour < 0; ++c) {
    if (!grid.blocked(c) && grid.secondIndex(c) + 1 < grid.secondAxis().count && grid.blocked(c + 1)) {
      blocked_neighbour = c;
    }
  }
  ASSERT_GE(blocked_neighbour, 0);
  const auto forge = [&](int cell, std::uint8_t bits) {
    std::vector<std::uint8_t> nodes = grid.packedNodes();
    nodes[static_cast<size_t>(cell)] |= bits;
    const GridAxis first = grid.firstAxis(), second = grid.secondAxis();
    return CSpaceGrid::fromPackedNodes({first, second}, nodes, model(), grid.checkedStepCount()).has_value();
  };
  EXPECT_TRUE(forge(blocked_neighbour, 0));
  EXPECT_FALSE(forge(blocked_neighbour, 1U << 3)) << "a step into a blocked node";
  EXPECT_FALSE(forge(blocked_neighbour, 1U << 5)) << "a bit no step has";
  EXPECT_FALSE(forge(grid.cellCount() - 1, 1U << 3)) << "a step out of the grid";
  std::vector<std::uint8_t> fewer = grid.packedNodes();
  fewer.pop_back();
  EXPECT_FALSE(CSpaceGrid::fromPackedNodes({grid.firstAxis(), grid.secondAxis()}, fewer, model(), 0).has_value());
}

TEST_F(GridCache, AFolderOrAPipeInPlaceOfTheFileIsUnreadable) {
  fs::create_directories(file_.path);
  EXPECT_EQ(readStatus(), GridCacheStatus::kUnreadable);
  EXPECT_EQ(writeGridCache(file_, drawnGrids()).status(), GridCacheStatus::kUnwritable);
  fs::remove(file_.path);
  ASSERT_EQ(::mkfifo(file_.path.c_str(), 0600), 0);
  EXPECT_EQ(readStatus(), GridCacheStatus::kUnreadable) << "and without waiting for a writer";
}

// Root may write anywhere, so the folder that cannot be made is one under a regular file.
TEST_F(GridCache, AFolderThatCannotBeWrittenIsNoError) {
  std::ofstream(dir_ / "a-file") << "not a folder";
  const fs::path unwritable = dir_ / "a-file" / "cache";
  const GridCacheFile file = gridCacheFile(unwritable, model(), 0, 0, JointRange{});
  EXPECT_EQ(writeGridCache(file, drawnGrids()).status(), GridCacheStatus::kUnwritable);
  const CachedPathPlanner cached = cachedPathPlanner(model(), 0, 0, JointRange{}, unwritable);
  EXPECT_EQ(cached.read, GridCacheStatus::kUnreadable);
  EXPECT_EQ(cached.write, GridCacheStatus::kUnwritable);
  expectSameGrid(cached.planner.grid(HeldPieces{}), drawn().grid(HeldPieces{}));
}

// The test: a corrupted file is detected at create(), the grids rebuilt and the file
// rewritten; and plans from cold grids, from the cache, and after the rebuild are the same bit for bit.
TEST_F(GridCache, CreateRebuildsACorruptFileAndPlansAreTheSameWithTheCache) {
  const GridSelection selection{0, 0.0};
  const auto cold = MotionPlanner::create(model(), selection);
  const auto first = MotionPlanner::create(model(), selection, dir_);  // builds and writes
  ASSERT_EQ(readStatus(), GridCacheStatus::kOk);
  const auto warm = MotionPlanner::create(model(), selection, dir_);  // reads
  Bytes corrupt = bytes();
  corrupt[corrupt.size() / 2] = static_cast<char>(corrupt[corrupt.size() / 2] ^ 1);
  replaceWith(corrupt);
  ASSERT_EQ(readStatus(), GridCacheStatus::kCorrupt);
  const auto rebuilt = MotionPlanner::create(model(), selection, dir_);
  EXPECT_EQ(readStatus(), GridCacheStatus::kOk) << "the corrupt file was not rewritten";
  ASSERT_TRUE(cold.ok() && first.ok() && warm.ok() && rebuilt.ok());

  // Moves of each held set, one from a moving start.
  std::vector<PlanRequest> moves;
  for (const char* label : {"none:STOW->L4", "coral:L2->STOW", "algae:STOW->NET"}) {
    const test::PublicMove& move = test::publicMove(label);
    moves.push_back({move.from, move.to, JointVector::Zero(2), move.pieces, 0, 0.0});
  }
  moves.push_back(moves.front());
  moves.back().start_velocity = JointVector{{0.3, 0.5}};
  int planned = 0;
  for (const PlanRequest& move : moves) {
    const auto expected = cold.value().plan(move);
    for (const auto* planner : {&first.value(), &warm.value(), &rebuilt.value()}) {
      const auto plan = planner->plan(move);
      ASSERT_EQ(plan.ok(), expected.ok());
      if (!plan.ok()) continue;
      ++planned;
      const double a = plan.value().trajectory->duration_s(), b = expected.value().trajectory->duration_s();
      EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << a << " s against " << b << " s";
      EXPECT_EQ(plan.value().waypoints, expected.value().waypoints);
    }
  }
  EXPECT_EQ(planned, 12);
}

}  // namespace
}  // namespace cyber::planner

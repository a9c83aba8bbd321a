#pragma once
// The grid cache (docs/design.md, "The grid cache"): the grids of one band of a scene's offsets
// kept in a file between starts, read back instead of built. A file is trusted only when all of it
// checks: magic, format version, key (grid_cache_key.hpp), grid count and sizes, a checksum of the
// payload and nodes a built grid can have; otherwise the grids are built and the file replaced.
// Writes are atomic (a temporary file renamed over the old one), so a reader never sees half a file.
// create() alone reads and writes it; nothing on the streaming path does.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <vector>

#include "cyber/planner/robot_model.hpp"
#include "cyber/result.hpp"
#include "path/cspace_grid.hpp"
#include "path/path_planner.hpp"

namespace cyber::planner {

enum class GridCacheStatus {
  kOk,
  kMissing,     // no file (the first start)
  kUnreadable,  // the file or its folder cannot be read
  kStale,       // another format version or key: other inputs or another planner
  kCorrupt,     // wrong magic, size or checksum, or nodes no built grid has
  kUnwritable,  // the folder cannot be made or written
};

template <class T>
using GridCacheResult = cyber::Result<T, GridCacheStatus>;

// Where a band's grids live, and the key they must have.
struct GridCacheFile {
  std::filesystem::path path;
  std::uint64_t key = 0;
};

// The file of `scene`'s band number `band_index` (0: the scene as drawn) in `dir`: one name per
// robot, scene and band, so a changed description overwrites its own files instead of adding files.
[[nodiscard]] GridCacheFile gridCacheFile(const std::filesystem::path& dir, const RobotModel& model, int scene,
                                          int band_index, const JointRange& band);

// The grids of every held set, by HeldPieces::index(), as they were built; or why not.
[[nodiscard]] GridCacheResult<std::vector<CSpaceGrid>> readGridCache(const GridCacheFile& file,
                                                                     const RobotModel& model);
// Writes the grids (creating the folder), replacing the file atomically; kUnwritable when it cannot.
[[nodiscard]] GridCacheResult<Done> writeGridCache(const GridCacheFile& file, std::span<const CSpaceGrid> grids);

// What became of a band's grids at create().
struct CachedPathPlanner {
  PathPlanner planner;
  GridCacheStatus read = GridCacheStatus::kMissing;   // kOk: the grids came from the file
  GridCacheStatus write = GridCacheStatus::kMissing;  // after a build: kOk when stored
};

// The path stage of scene index `scene`'s band: its grids from the file when it checks, else built
// and stored. Without a folder, or with one that cannot be written, the grids are built and
// nothing fails: the cache only saves time.
[[nodiscard]] CachedPathPlanner cachedPathPlanner(const RobotModel& model, int scene, int band_index,
                                                  const JointRange& band,
                                                  const std::optional<std::filesystem::path>& dir);

}  // namespace cyber::planner

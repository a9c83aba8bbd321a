#include "path/grid_cache.hpp"

#include <sys/stat.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <string>
#include <system_error>
#include <utility>

#include "path/grid_cache_key.hpp"

namespace cyber::planner {
namespace {

// The file: a header of fixed size, then per grid its checked-step count (4 bytes) and its
// packedNodes(). Numbers are little-endian whatever the machine's order. The header's two counts
// are the first axis's nodes and the nodes of the other axes together (1 for one joint).
constexpr std::array<std::uint8_t, 8> kMagic = {'C', 'Y', 'G', 'R', 'I', 'D', 'S', 0};
constexpr size_t kVersionAt = 8;
constexpr size_t kGridCountAt = 12;
constexpr size_t kKeyAt = 16;
constexpr size_t kFirstCountAt = 24;
constexpr size_t kSecondCountAt = 28;
constexpr size_t kPayloadSizeAt = 32;
constexpr size_t kChecksumAt = 40;
constexpr size_t kHeaderSize = 48;
constexpr size_t kCheckedStepsSize = 4;
constexpr int kBitsPerByte = 8;
constexpr std::uint64_t kLowByte = 0xff;
// A robot's name in a file name: this many characters at most, others than these replaced.
constexpr size_t kLongestName = 64;

using Bytes = std::vector<std::uint8_t>;

void put(Bytes& out, size_t at, std::uint64_t value, size_t size) {
  for (size_t i = 0; i < size; ++i) out[at + i] = static_cast<std::uint8_t>((value >> (kBitsPerByte * i)) & kLowByte);
}

std::uint64_t get(const Bytes& in, size_t at, size_t size) {
  std::uint64_t value = 0;
  for (size_t i = 0; i < size; ++i) value |= static_cast<std::uint64_t>(in[at + i]) << (kBitsPerByte * i);
  return value;
}

std::uint64_t checksum(std::span<const std::uint8_t> payload) {
  Fnv1a64 hash;
  hash.bytes(payload);
  return hash.value();
}

// The node counts of the header: the first axis's, and the other axes' product.
struct Axes {
  PerJoint<GridAxis> axes;
  std::uint64_t first = 0;
  std::uint64_t rest = 1;
  [[nodiscard]] std::uint64_t nodes() const { return first * rest; }
};

Axes countsOf(const PerJoint<GridAxis>& axes) {
  Axes out{axes, static_cast<std::uint64_t>(axes[0].count), 1};
  for (int d = 1; d < axes.size(); ++d) out.rest *= static_cast<std::uint64_t>(axes[d].count);
  return out;
}

// Reads up to `size` bytes; fewer at the file's end.
GridCacheResult<Bytes> readBytes(int fd, size_t size) {
  Bytes out(size);
  size_t done = 0;
  while (done < size) {
    const ssize_t n = ::read(fd, out.data() + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return GridCacheStatus::kUnreadable;
    if (n == 0) break;
    done += static_cast<size_t>(n);
  }
  out.resize(done);
  return out;
}

bool writeAll(int fd, const Bytes& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

// The header's own checks, in the order that tells a stale file from a corrupt one.
GridCacheStatus checkHeader(const Bytes& header, const GridCacheFile& file, const RobotModel& model, const Axes& axes,
                            std::uint64_t file_size) {
  if (header.size() < kHeaderSize || !std::equal(kMagic.begin(), kMagic.end(), header.begin())) {
    return GridCacheStatus::kCorrupt;
  }
  if (get(header, kVersionAt, 4) != kGridFormatVersion || get(header, kKeyAt, 8) != file.key) {
    return GridCacheStatus::kStale;
  }
  const auto grids = static_cast<std::uint64_t>(model.pieceSetCount());
  const std::uint64_t bytes =
      axes.nodes() * static_cast<std::uint64_t>(CSpaceGrid::packedBytesPerNode(axes.axes.size()));
  const std::uint64_t payload = grids * (kCheckedStepsSize + bytes);
  const bool sizes_agree = get(header, kGridCountAt, 4) == grids && get(header, kFirstCountAt, 4) == axes.first &&
                           get(header, kSecondCountAt, 4) == axes.rest && get(header, kPayloadSizeAt, 8) == payload &&
                           file_size == kHeaderSize + payload;
  return sizes_agree ? GridCacheStatus::kOk : GridCacheStatus::kCorrupt;
}

// Closes its descriptor on every way out.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

GridCacheFile gridCacheFile(const std::filesystem::path& dir, const RobotModel& model, int scene, int band_index,
                            const JointRange& band) {
  std::string name;
  for (const char c : model.name.substr(0, kLongestName)) {
    const bool plain =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
    name.push_back(plain ? c : '_');
  }
  if (name.empty()) name = "robot";
  name.append(".scene-").append(std::to_string(scene)).append(".band-").append(std::to_string(band_index));
  name.append(".grids");
  const Scene& drawn = model.scenes[static_cast<size_t>(scene)];
  return {dir / name, gridCacheKey(model, drawn, band)};
}

GridCacheResult<std::vector<CSpaceGrid>> readGridCache(const GridCacheFile& file, const RobotModel& model) {
  // O_NONBLOCK: a pipe in the file's place must not stop the start-up (regular files ignore it).
  Fd in{::open(file.path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
  if (in.fd < 0) return errno == ENOENT ? GridCacheStatus::kMissing : GridCacheStatus::kUnreadable;
  struct stat status {};
  if (::fstat(in.fd, &status) != 0 || !S_ISREG(status.st_mode)) return GridCacheStatus::kUnreadable;
  const Axes axes = countsOf(CSpaceGrid::axesOf(model));
  GridCacheResult<Bytes> header = readBytes(in.fd, kHeaderSize);
  if (!header) return header.error();
  const GridCacheStatus checked =
      checkHeader(header.value(), file, model, axes, static_cast<std::uint64_t>(status.st_size));
  if (checked != GridCacheStatus::kOk) return checked;
  const size_t payload_size = static_cast<size_t>(status.st_size) - kHeaderSize;
  GridCacheResult<Bytes> payload = readBytes(in.fd, payload_size);
  if (!payload) return payload.error();
  const Bytes& bytes = payload.value();
  if (bytes.size() != payload_size || checksum(bytes) != get(header.value(), kChecksumAt, 8)) {
    return GridCacheStatus::kCorrupt;
  }
  const size_t nodes =
      static_cast<size_t>(axes.nodes()) * static_cast<size_t>(CSpaceGrid::packedBytesPerNode(axes.axes.size()));
  std::vector<CSpaceGrid> grids;
  grids.reserve(static_cast<size_t>(model.pieceSetCount()));
  for (size_t at = 0; at < bytes.size(); at += kCheckedStepsSize + nodes) {
    const auto checked_steps = static_cast<int>(get(bytes, at, kCheckedStepsSize));
    std::optional<CSpaceGrid> grid = CSpaceGrid::fromPackedNodes(
        axes.axes, std::span(bytes).subspan(at + kCheckedStepsSize, nodes), model, checked_steps);
    if (!grid || checked_steps < 0) return GridCacheStatus::kCorrupt;
    grids.push_back(std::move(*grid));
  }
  return grids;
}

GridCacheResult<Done> writeGridCache(const GridCacheFile& file, std::span<const CSpaceGrid> grids) {
  if (grids.empty()) return GridCacheStatus::kUnwritable;
  const Axes axes = countsOf(grids.front().axes());
  Bytes bytes(kHeaderSize);
  for (const CSpaceGrid& grid : grids) {
    const size_t at = bytes.size();
    bytes.resize(at + kCheckedStepsSize);
    put(bytes, at, static_cast<std::uint32_t>(grid.checkedStepCount()), kCheckedStepsSize);
    const std::vector<std::uint8_t> nodes = grid.packedNodes();
    bytes.insert(bytes.end(), nodes.begin(), nodes.end());
  }
  std::copy(kMagic.begin(), kMagic.end(), bytes.begin());
  put(bytes, kVersionAt, kGridFormatVersion, 4);
  put(bytes, kGridCountAt, grids.size(), 4);
  put(bytes, kKeyAt, file.key, 8);
  put(bytes, kFirstCountAt, axes.first, 4);
  put(bytes, kSecondCountAt, axes.rest, 4);
  put(bytes, kPayloadSizeAt, bytes.size() - kHeaderSize, 8);
  put(bytes, kChecksumAt, checksum(std::span(bytes).subspan(kHeaderSize)), 8);

  std::error_code error;
  std::filesystem::create_directories(file.path.parent_path(), error);
  if (error) return GridCacheStatus::kUnwritable;
  // Unsynced: a file cut short by a power loss fails its checks and is rebuilt.
  std::string temporary = file.path.string() + ".XXXXXX";
  const int fd = ::mkstemp(temporary.data());
  if (fd < 0) return GridCacheStatus::kUnwritable;
  const bool written = writeAll(fd, bytes);
  const bool closed = ::close(fd) == 0;
  if (!written || !closed || std::rename(temporary.c_str(), file.path.c_str()) != 0) {
    ::unlink(temporary.c_str());
    return GridCacheStatus::kUnwritable;
  }
  return Done{};
}

CachedPathPlanner cachedPathPlanner(const RobotModel& model, int scene, int band_index, const JointRange& band,
                                    const std::optional<std::filesystem::path>& dir) {
  const Scene& drawn = model.scenes[static_cast<size_t>(scene)];
  if (!dir) return {PathPlanner(model, drawn, band), GridCacheStatus::kMissing, GridCacheStatus::kMissing};
  const GridCacheFile file = gridCacheFile(*dir, model, scene, band_index, band);
  GridCacheResult<std::vector<CSpaceGrid>> read = readGridCache(file, model);
  if (read)
    return {PathPlanner(model, drawn, band, std::move(read).value()), GridCacheStatus::kOk, GridCacheStatus::kMissing};
  CachedPathPlanner out{PathPlanner(model, drawn, band), read.status(), GridCacheStatus::kOk};
  std::vector<CSpaceGrid> grids;
  for (int set = 0; set < model.pieceSetCount(); ++set) grids.push_back(out.planner.grid(HeldPieces::fromIndex(set)));
  out.write = writeGridCache(file, grids).status();
  return out;
}

}  // namespace cyber::planner

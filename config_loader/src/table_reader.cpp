#include "table_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string_view>

namespace cyber::config::detail {
namespace {

[[noreturn]] void failAt(const std::string& path, const std::string& problem) {
  throw ConfigError(path, path + ": " + problem);
}

std::string describe(double x) { return fmt::format("{:g}", x); }

double numberFrom(const toml::node& node, const std::string& path, Bounds bounds) {
  if (!node.is_number()) failAt(path, "expected a number");
  const double x = node.is_integer() ? static_cast<double>(*node.value<int64_t>()) : *node.value<double>();
  if (!std::isfinite(x)) failAt(path, "must be a finite number, got " + describe(x));
  const bool below = bounds.min_exclusive ? x <= bounds.min : x < bounds.min;
  if (below || x > bounds.max) {
    std::string range = bounds.min_exclusive ? "> " + describe(bounds.min) : ">= " + describe(bounds.min);
    if (bounds.max < 1e300) range += " and <= " + describe(bounds.max);
    failAt(path, "out of range: must be " + range + ", got " + describe(x));
  }
  return x;
}

Eigen::Vector2d pointFrom(const toml::node& node, const std::string& path, Bounds bounds = kAny) {
  const toml::array* a = node.as_array();
  if (a == nullptr || a->size() != 2) failAt(path, "expected a pair [x, y] of numbers");
  return {numberFrom((*a)[0], path + "[0]", bounds), numberFrom((*a)[1], path + "[1]", bounds)};
}

std::string lowerCase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// A key in lower case without its unit suffix ("kS_volts" -> "ks"): a key written without its
// unit, or in another case, is the same key.
std::string stem(const std::string& key) {
  static constexpr std::array<std::string_view, 11> kUnits{"_m",  "_rad", "_deg",  "_volts", "_amps", "_s",
                                                           "_hz", "_kg",  "_kgm2", "_nm",    "_rpm"};
  const std::string lower = lowerCase(key);
  for (std::string_view unit : kUnits) {
    if (lower.size() > unit.size() && lower.ends_with(unit)) return lower.substr(0, lower.size() - unit.size());
  }
  return lower;
}

size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// How far an unknown key is from a known one: 0 when they differ only in case or unit suffix.
size_t keyDistance(const std::string& unknown, const std::string& known) {
  return std::min(editDistance(lowerCase(unknown), lowerCase(known)), editDistance(stem(unknown), stem(known)));
}

// The known key an unknown one most likely meant: the same up to case and unit suffix, or with
// `typos` at most two edits away (one for keys of up to four letters).
std::string likelyKey(const std::string& unknown, const std::set<std::string>& known, bool typos) {
  const size_t most = !typos ? 0 : unknown.size() <= 4 ? 1 : 2;
  std::string best;
  size_t best_distance = most + 1;
  for (const std::string& key : known) {
    const size_t distance = key == unknown ? most + 1 : keyDistance(unknown, key);
    if (distance < best_distance) {
      best = key;
      best_distance = distance;
    }
  }
  return best;
}

std::string unknownKeyProblem(const std::string& key, const std::string& likely) {
  std::string problem = "unknown key '";
  problem.append(key).append("'");
  if (!likely.empty()) problem.append(" (did you mean '").append(likely).append("'?)");
  return problem;
}

}  // namespace

TableReader::TableReader(const toml::table& table, std::string path) : table_(table), path_(std::move(path)) {}

std::string TableReader::pathOf(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

void TableReader::fail(const std::string& key, const std::string& problem) const { failAt(pathOf(key), problem); }

const toml::node& TableReader::require(const std::string& key) {
  const toml::node* node = table_.get(key);
  asked_.insert(key);
  if (node == nullptr) {
    // A key written without its unit (origin for origin_m) is named, not reported as missing.
    for (const auto& [k, v] : table_) {
      const std::string written(k.str());
      if (!used_.contains(written) && likelyKey(written, {key}, false) == key) {
        fail(written, unknownKeyProblem(written, key));
      }
    }
    fail(key, "missing key");
  }
  used_.insert(key);
  return *node;
}

double TableReader::number(const std::string& key, Bounds bounds) {
  return numberFrom(require(key), pathOf(key), bounds);
}

std::optional<double> TableReader::optionalNumber(const std::string& key, Bounds bounds) {
  if (!has(key)) return std::nullopt;
  return number(key, bounds);
}

long long TableReader::integer(const std::string& key, long long min, long long max) {
  const toml::node& node = require(key);
  if (!node.is_integer()) fail(key, "expected an integer");
  const long long x = *node.value<int64_t>();
  if (x < min || x > max) {
    fail(key, "out of range: must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " +
                  std::to_string(x));
  }
  return x;
}

bool TableReader::boolean(const std::string& key) {
  const toml::node& node = require(key);
  if (!node.is_boolean()) fail(key, "expected true or false");
  return *node.value<bool>();
}

std::string TableReader::string(const std::string& key, const std::string& what) {
  const toml::node& node = require(key);
  if (!node.is_string()) fail(key, "expected " + what);
  return *node.value<std::string>();
}

std::vector<std::string> TableReader::strings(const std::string& key, const std::string& what) {
  const toml::array& a = array(key);
  std::vector<std::string> out;
  for (size_t i = 0; i < a.size(); ++i) {
    if (!a[i].is_string()) fail(key, "element " + std::to_string(i) + " must be " + what);
    out.push_back(*a[i].value<std::string>());
  }
  return out;
}

Eigen::Vector2d TableReader::vector2(const std::string& key, Bounds bounds) {
  return pointFrom(require(key), pathOf(key), bounds);
}

planner::JointVector TableReader::jointVector(const std::string& key, int joints, Bounds bounds) {
  const std::string path = pathOf(key);
  const toml::array* a = require(key).as_array();
  if (a == nullptr || a->size() != static_cast<size_t>(joints)) {
    failAt(path, joints == 1 ? "expected [q] : one number, for the robot's one joint"
                             : fmt::format("expected {} numbers, one per joint in chain order", joints));
  }
  planner::JointVector out(joints);
  for (int j = 0; j < joints; ++j)
    out[j] = numberFrom((*a)[static_cast<size_t>(j)], path + "[" + std::to_string(j) + "]", bounds);
  return out;
}

const toml::array& TableReader::array(const std::string& key) {
  const toml::array* a = require(key).as_array();
  if (a == nullptr) fail(key, "expected an array");
  return *a;
}

std::vector<planner::ConvexPolygon> TableReader::polygons(const std::string& key) {
  const toml::array& list = array(key);
  if (list.empty()) fail(key, "expected at least one polygon");
  std::vector<planner::ConvexPolygon> out;
  for (size_t i = 0; i < list.size(); ++i)
    out.push_back(polygonFrom(list[i], pathOf(key) + "[" + std::to_string(i) + "]"));
  return out;
}

planner::ConvexPolygon TableReader::polygon(const std::string& key) { return polygonFrom(require(key), pathOf(key)); }

TableReader TableReader::table(const std::string& key) { return tableAt(require(key), pathOf(key)); }

TableReader TableReader::optionalTable(const std::string& key) {
  static const toml::table kEmpty;
  return has(key) ? table(key) : TableReader(kEmpty, pathOf(key));
}

std::vector<std::string> TableReader::keys() {
  std::vector<std::string> out;
  for (const auto& [k, v] : table_) {
    out.emplace_back(k.str());
  }
  return out;
}

std::vector<std::string> TableReader::keysInFileOrder() {
  struct Placed {
    toml::source_position at;
    std::size_t sorted_index;  // ties (keys without a source) keep toml++'s order
    std::string key;
  };
  std::vector<Placed> placed;
  for (const auto& [k, v] : table_) placed.push_back(Placed{v.source().begin, placed.size(), std::string(k.str())});
  // std::sort, not std::stable_sort: the latter's temporary buffer (operator new, nothrow) is freed
  // in a way that the allocation-counting tests' replaced operators see as a mismatch under ASan.
  std::sort(placed.begin(), placed.end(), [](const Placed& a, const Placed& b) {
    if (a.at.line != b.at.line) return a.at.line < b.at.line;
    if (a.at.column != b.at.column) return a.at.column < b.at.column;
    return a.sorted_index < b.sorted_index;
  });
  std::vector<std::string> out;
  for (Placed& p : placed) out.push_back(std::move(p.key));
  return out;
}

void TableReader::finish() const {
  for (const auto& [k, v] : table_) {
    const std::string key(k.str());
    if (!used_.contains(key)) fail(key, unknownKeyProblem(key, likelyKey(key, asked_, true)));
  }
}

TableReader tableAt(const toml::node& node, const std::string& path) {
  const toml::table* t = node.as_table();
  if (t == nullptr) failAt(path, "expected a table");
  return TableReader(*t, path);
}

planner::ConvexPolygon polygonFrom(const toml::node& node, const std::string& path) {
  const toml::array* a = node.as_array();
  if (a == nullptr) failAt(path, "expected a polygon: an array of [x, y] vertices");
  std::vector<planner::Point2> vertices;
  for (size_t i = 0; i < a->size(); ++i) vertices.push_back(pointFrom((*a)[i], path + "[" + std::to_string(i) + "]"));
  auto polygon = planner::ConvexPolygon::fromVertices(std::move(vertices));
  if (!polygon) failAt(path, polygon.error().message);
  return std::move(polygon).value();
}

}  // namespace cyber::config::detail

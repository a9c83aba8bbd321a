#pragma once
// Strict reading of one TOML table: every key read is remembered, so finish() can reject the
// keys nobody asked for. All problems throw ConfigError naming the full key path.

#include <toml++/toml.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "cyber/config/load_config.hpp"

namespace cyber::config::detail {

struct Bounds {
  double min = -1e300;
  double max = 1e300;
  bool min_exclusive = false;
};
inline constexpr Bounds kPositive{0.0, 1e300, true};
inline constexpr Bounds kNonNegative{0.0, 1e300, false};
inline constexpr Bounds kAny{};

class TableReader {
 public:
  TableReader(const toml::table& table, std::string path);

  [[nodiscard]] double number(const std::string& key, Bounds bounds = kAny);
  [[nodiscard]] std::optional<double> optionalNumber(const std::string& key, Bounds bounds = kAny);
  [[nodiscard]] long long integer(const std::string& key, long long min, long long max);
  [[nodiscard]] bool boolean(const std::string& key);
  // `what` names what the string is for the message of a wrong type ("a joint's name").
  [[nodiscard]] std::string string(const std::string& key, const std::string& what = "a string");
  [[nodiscard]] std::vector<std::string> strings(const std::string& key, const std::string& what = "a string");
  // A 2-vector [x, y] of finite numbers.
  [[nodiscard]] Eigen::Vector2d vector2(const std::string& key, Bounds bounds = kAny);
  // One number per joint: an array of `joints` numbers.
  [[nodiscard]] planner::JointVector jointVector(const std::string& key, int joints, Bounds bounds = kAny);
  // A list of convex polygons [[[x, y], ...], ...] (at least one).
  [[nodiscard]] std::vector<planner::ConvexPolygon> polygons(const std::string& key);
  // One convex polygon [[x, y], ...].
  [[nodiscard]] planner::ConvexPolygon polygon(const std::string& key);
  // Also remembers the key as one this table may have, for finish()'s suggestions.
  [[nodiscard]] bool has(const std::string& key) const {
    asked_.insert(key);
    return table_.contains(key);
  }
  [[nodiscard]] bool isArray(const std::string& key) const {
    const toml::node* node = table_.get(key);
    return node != nullptr && node->is_array();
  }
  [[nodiscard]] TableReader table(const std::string& key);
  // The table, or an empty one with the same path when the file leaves it out.
  [[nodiscard]] TableReader optionalTable(const std::string& key);
  [[nodiscard]] const toml::array& array(const std::string& key);
  // Every key of this table, for tables whose keys are names (obstacles, motors).
  [[nodiscard]] std::vector<std::string> keys();
  // The same in the order the file gives them (toml++ keeps a table's keys sorted), for lists
  // whose order means something (named poses: the first is the robot's starting pose).
  [[nodiscard]] std::vector<std::string> keysInFileOrder();

  // Rejects keys that were never read, naming the likely intended key when one is close.
  void finish() const;

  [[nodiscard]] std::string pathOf(const std::string& key) const;
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;

 private:
  const toml::node& require(const std::string& key);

  const toml::table& table_;
  std::string path_;
  std::set<std::string> used_;
  mutable std::set<std::string> asked_;  // every key read or looked for
};

TableReader tableAt(const toml::node& node, const std::string& path);
planner::ConvexPolygon polygonFrom(const toml::node& node, const std::string& path);

}  // namespace cyber::config::detail

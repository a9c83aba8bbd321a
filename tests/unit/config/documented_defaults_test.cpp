// docs/configuration.md's [planner] table says each key's default: it must be the loader's, and
// every key the loader reads must be in it (docs/configuration.md, "Planner").

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>

#include "cyber/config/load_config.hpp"
#include "shipped_robots.hpp"

namespace cyber::config {
namespace {

std::string fileText(const std::string& relative) {
  std::ifstream in(test::sourceFile(relative));
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Key -> default column of the table's rows "| `planner.KEY` | type | default | meaning |".
std::map<std::string, std::string> documentedDefaults() {
  std::map<std::string, std::string> out;
  std::istringstream doc(fileText("docs/configuration.md"));
  for (std::string line; std::getline(doc, line);) {
    if (!line.starts_with("| `planner.")) continue;
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream row(line.substr(1));
    while (std::getline(row, cell, '|')) cells.push_back(cell.substr(1, cell.size() - 2));
    if (cells.size() < 3) continue;
    out[cells[0].substr(1, cells[0].size() - 2)] = cells[2];
  }
  return out;
}

TEST(DocumentedDefaults, ThePlannerTableGivesTheLoadersDefaults) {
  const auto documented = documentedDefaults();
  const Config minimal = parseConfig(fileText("tests/fixtures/minimal-robot.toml"), "minimal-robot.toml");
  int planner_keys = 0;
  for (const SettingOrigin& s : minimal.settings) {
    if (!s.key.starts_with("planner.")) continue;
    ++planner_keys;
    const auto it = documented.find(s.key);
    ASSERT_NE(it, documented.end()) << s.key << " is not in docs/configuration.md";
    if (s.source == SettingSource::kDerived) {
      EXPECT_EQ(it->second, "derived") << s.key;
    } else {
      EXPECT_EQ(std::stod(it->second), std::stod(s.value)) << s.key << ": documented " << it->second;
    }
  }
  EXPECT_EQ(static_cast<size_t>(planner_keys), documented.size());
  EXPECT_EQ(planner_keys, 27);
}

}  // namespace
}  // namespace cyber::config

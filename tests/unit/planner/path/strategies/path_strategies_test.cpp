// The registry of path strategies (path_strategies.hpp): every strategy of the folder listed once,
// with its reason, in the order each names; the whole list is what candidates() tries. Each
// strategy's own behaviour is in its own test (shortcut_search_path_test.cpp and its siblings).

#include "path/strategies/path_strategies.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "public_moves.hpp"
#include "reference_model.hpp"

namespace cyber::planner {
namespace {

TEST(PathStrategies, AreTriedInTheirDocumentedOrderEachWithItsReason) {
  std::vector<std::string_view> names;
  std::set<std::string_view> unique;
  for (const PathStrategy& s : pathStrategies()) {
    names.push_back(s.name);
    unique.insert(s.name);
    EXPECT_GT(s.reason.size(), 20u) << s.name;
    EXPECT_NE(s.run, nullptr) << s.name;
  }
  EXPECT_EQ(unique.size(), names.size());
  EXPECT_EQ(names.size(), builtInPathStrategies().size()) << "no strategy registered outside its folder";
  // Shortcuts and other ways come before the shape search, which starts from the fastest of them;
  // the synchronised candidate is judged against the fastest of all.
  const std::vector<std::string_view> expected{"shape the straight segment", "shortcut", "other ways round",
                                               "shape the fastest path", "synchronise the joints"};
  EXPECT_EQ(names, expected);
  const std::span<const PathStrategy> all = pathStrategies();
  EXPECT_TRUE(std::is_sorted(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.order < b.order; }));
}

// With every strategy, candidates() is the first path and what the list adds, fastest first.
TEST(PathStrategies, TheWholeListIsWhatCandidatesTries) {
  const PathPlanner& planner = test::referencePathPlanner();
  for (const char* move : {"none:STOW->L4", "none:L1->NET", "coral:STOW->L2"}) {
    const test::PublicMove& m = test::publicMove(move);
    const auto all = planner.candidates(m.from, m.to, m.pieces);
    const auto listed = planner.candidates(m.from, m.to, m.pieces, JointVector::Zero(2), pathStrategies());
    ASSERT_TRUE(all.ok() && listed.ok()) << move;
    ASSERT_EQ(all.value().size(), listed.value().size()) << move;
    for (size_t i = 0; i < all.value().size(); ++i) EXPECT_EQ(all.value()[i].method, listed.value()[i].method);
  }
}

}  // namespace
}  // namespace cyber::planner

// The open list's heap against a sorted multiset on seeded random sequences of pushes and pops,
// with many equal keys (A*'s f ties on a grid).

#include "math/quaternary_heap.hpp"

#include <random>
#include <set>
#include <utility>

#include <gtest/gtest.h>

namespace cyber::planner {
namespace {

using Item = std::pair<int, int>;  // (key, serial): a total order, as A*'s entries have

struct Smaller {
  bool operator()(const Item& a, const Item& b) const { return a < b; }
};

TEST(QuaternaryHeap, PopsInTheOrderOfASortedMultisetOverSeededSequences) {
  for (unsigned seed = 1; seed <= 200; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> key(0, static_cast<int>(seed % 7 == 0 ? 3 : 1000));
    std::bernoulli_distribution pushing(seed % 2 == 0 ? 0.6 : 0.5);
    QuaternaryHeap<Item, Smaller> heap;
    std::multiset<Item> reference;
    int serial = 0;
    for (int step = 0; step < 2000; ++step) {
      if (reference.empty() || pushing(rng)) {
        const Item item{key(rng), serial++};
        heap.push(item);
        reference.insert(item);
      } else {
        ASSERT_EQ(heap.top(), *reference.begin()) << "seed " << seed << " step " << step;
        ASSERT_EQ(heap.pop(), *reference.begin()) << "seed " << seed << " step " << step;
        reference.erase(reference.begin());
      }
      ASSERT_EQ(heap.size(), reference.size());
    }
    while (!reference.empty()) {
      ASSERT_EQ(heap.pop(), *reference.begin()) << "seed " << seed;
      reference.erase(reference.begin());
    }
    EXPECT_TRUE(heap.empty());
  }
}

TEST(QuaternaryHeap, OneItemAndClear) {
  QuaternaryHeap<Item, Smaller> heap;
  heap.push({5, 0});
  EXPECT_EQ(heap.pop(), Item(5, 0));
  EXPECT_TRUE(heap.empty());
  heap.push({2, 0});
  heap.push({1, 1});
  heap.clear();
  EXPECT_TRUE(heap.empty());
}

}  // namespace
}  // namespace cyber::planner

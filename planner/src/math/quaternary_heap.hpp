#pragma once
// A min-heap with four children per node, for A*'s open list. Popping dominates the search
// (docs/performance.md, "Planner"); four children halve the heap's depth against a binary heap
// and keep each node's children in one cache line, at the cost of three more comparisons a level.

#include <cstddef>
#include <vector>

namespace cyber::planner {

// `Before(a, b)`: a is popped before b. With a total order the pops do not depend on the heap's
// layout, so a search's result is the same whatever heap it uses.
template <class T, class Before>
class QuaternaryHeap {
 public:
  void reserve(size_t n) { items_.reserve(n); }
  [[nodiscard]] bool empty() const { return items_.empty(); }
  [[nodiscard]] size_t size() const { return items_.size(); }
  [[nodiscard]] const T& top() const { return items_.front(); }
  void clear() { items_.clear(); }

  void push(const T& item) {
    size_t at = items_.size();
    items_.push_back(item);
    while (at > 0) {
      const size_t parent = (at - 1) / 4;
      if (!before_(item, items_[parent])) break;
      items_[at] = items_[parent];
      at = parent;
    }
    items_[at] = item;
  }

  // Removes and returns the first item; the heap must not be empty.
  T pop() {
    const T first = items_.front();
    const T last = items_.back();
    items_.pop_back();
    const size_t n = items_.size();
    if (n == 0) return first;
    size_t at = 0;
    for (;;) {
      const size_t child = 4 * at + 1;
      if (child >= n) break;
      size_t best = child;
      const size_t end = child + 4 < n ? child + 4 : n;
      for (size_t c = child + 1; c < end; ++c) {
        if (before_(items_[c], items_[best])) best = c;
      }
      if (!before_(items_[best], last)) break;
      items_[at] = items_[best];
      at = best;
    }
    items_[at] = last;
    return first;
  }

 private:
  std::vector<T> items_;
  [[no_unique_address]] Before before_{};
};

}  // namespace cyber::planner

#pragma once
// Test access to a LatestValue: a writer stopped in the middle of a store, as on one CPU when a
// higher-priority reader preempts it (latest_value.hpp, tryLoad).

#include "cyber/daemon/io/latest_value.hpp"

namespace cyber::daemon::io {

template <class T>
struct LatestValueTestPeer {
  // The sequence is odd from beginStore to endStore, as while the words are being written.
  static void beginStore(LatestValue<T>& latest) { latest.sequence_.fetch_add(1); }
  static void endStore(LatestValue<T>& latest) { latest.sequence_.fetch_add(1); }
};

}  // namespace cyber::daemon::io

#pragma once
// Tests build chains of programs step by step: a splice kept in `out`, its dropped requests
// appended to `dropped` (as the coordinator keeps them). False, and nothing changed, when the
// chain is full.

#include <cstdint>
#include <utility>
#include <vector>

#include "cyber/daemon/program.hpp"

namespace cyber::daemon::test {

inline bool spliceInto(const Program& base, SpliceRequest request, Program& out, std::vector<std::int64_t>& dropped) {
  auto spliced = Program::splice(base, std::move(request));
  if (!spliced) return false;
  out = std::move(spliced->program);
  dropped.insert(dropped.end(), spliced->dropped_requests.begin(), spliced->dropped_requests.end());
  return true;
}

}  // namespace cyber::daemon::test

#pragma once
// How long a stage of a plan took (StageTimesMs), from one steady clock for every stage.

#include <chrono>

namespace cyber::planner {

inline double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace cyber::planner

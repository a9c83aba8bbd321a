// Citations that exist: eqs. 7-8 (algorithm.md section 2.3, algorithm.md §1), docs/design.md,
// "The motion gate", good.hpp, lib/good.hpp, cyberplanner/arm_goal_t.hpp, config.cpp,
// lib/.../good.hpp
#include <lcm/lcm-cpp.hpp>

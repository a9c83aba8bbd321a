#pragma once
// Plausible random robots that no one tuned the planner for (docs/testing.md, "Random robots"):
// FRC-sized chains of random joint types, origins, ranges and link outlines, held pieces, a
// floor, a robot body and 1-3 field elements in a scene with an offset range, drives from the
// shipped configs' motors (and WPILib's Kraken X44, NEO Vortex) geared to cross a joint's range in
// 0.3-1.5 s, feedforward or rigid body, and named poses drawn clear of the obstacles. Each robot
// is written as a description in the format of docs/configuration.md and loaded through the
// config loader, so a failing robot is a file cyber-plan reads as it is.

#include <string>

#include "cyber/config/load_config.hpp"

namespace cyber::test {

struct RandomRobot {
  unsigned seed = 0;
  std::string toml;         // the whole description, for cyber-plan --config
  config::Config config;    // toml, loaded
  double free_share = 0.0;  // of poses uniform in the limits that keep the clearance (no piece, offset 0)
};

// How many joints the robot of `seed` has: 1, 2 or 3 in turn (seeds 1, 4, 7, ... two, as every
// seed had before the planner planned 1 to 3 joints, so those robots are drawn as they were).
int randomJointCount(unsigned seed);

// The robot of `seed` with `joint_count` joints (1 to 3; randomJointCount(seed) when left out),
// the same on every machine (its own mt19937 and arithmetic on the draws; no std::
// distributions, whose results the standard leaves open). Drawn robots with too little free space
// for moves (a pose set that fits nowhere, under a quarter of the poses clear) are drawn again
// from the same stream.
RandomRobot randomRobot(unsigned seed);
RandomRobot randomRobot(unsigned seed, int joint_count);

// Writes the robot's description and then `trailer` (comments: the failing moves) to `path`, a
// reproducer; false when it cannot.
bool saveRandomRobot(const RandomRobot& robot, const std::string& path, const std::string& trailer);

}  // namespace cyber::test

#pragma once
// The parts of a random robot, each drawn on its own (random_robot.hpp puts them together).

#include <vector>

#include "random_robot_draws.hpp"

namespace cyber::test::random_robot {

// `joint_count` joints in chain order, named joint0, joint1, ...; the first sits above a robot
// body `body_height_m` tall.
std::vector<JointDraw> drawChain(Draws& d, int joint_count, double body_height_m);

// One or two pieces held at the tip of the chain's last link.
std::vector<PieceDraw> drawPieces(Draws& d, const JointDraw& last);

// Each joint's motors, geared to cross its range in 0.3-1.5 s and to hold everything it carries
// (with every piece held) against gravity with room to accelerate; feedforward gains derived
// from the same bodies when the drives are not rigid-body.
std::vector<DriveDraw> drawDrives(Draws& d, const std::vector<JointDraw>& chain, const std::vector<PieceDraw>& pieces,
                                  bool rigid_body);

}  // namespace cyber::test::random_robot

#pragma once
// The columns of a trajectory CSV (docs/design.md, the cyber-plan command line): t, then for each joint in
// chain order NAME_pos, NAME_vel, NAME_acc, NAME_volts, NAME_amps, the joint named as the robot
// description names it. cyber-plan writes it, cyber-plot reads it.

#include <string>

namespace cyber::plot {

inline constexpr const char* kCsvColumns[] = {"pos", "vel", "acc", "volts", "amps"};

inline std::string csvColumn(const std::string& joint_name, const char* column) { return joint_name + "_" + column; }

}  // namespace cyber::plot

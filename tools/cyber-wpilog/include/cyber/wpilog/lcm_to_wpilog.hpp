#pragma once
// An lcm-logger log of a cyber-planner session as WPILOG entries under /CyberPlanner/ (the names
// and units are listed in docs/operations.md, "AdvantageScope"). Timestamps are the logger's
// receive times in µs from the log's earliest event (not its first: lcm-logger's file order is not
// quite time order); trajectory samples are placed on that clock through the offset between the
// message's receive time and its utime.

#include <cstdint>
#include <string>

#include "cyber/config/daemon_settings.hpp"
#include "cyber/planner.hpp"
#include "cyber/result.hpp"
#include "cyber/wpilog/wpilog_status.hpp"
#include "cyber/wpilog/wpilog_writer.hpp"

namespace cyber::wpilog {

// What the logged mechanism drawings need of the robot: its chain of N joints (1 to
// planner::kMaxJoints) and where each link's Mechanism2d ligament ends, in that link's frame: at
// the next joint's origin for a link that carries one, so that each ligament starts where its
// joint is; at the far end of its outline along its own x axis for the last link.
struct MechanismGeometry {
  planner::JointChain chain;
  planner::PerJoint<planner::Point2> ligament_end_m;
};
MechanismGeometry mechanismGeometry(const planner::RobotModel& robot);

struct ConvertStats {
  int64_t events = 0;       // events in the LCM log
  int64_t converted = 0;    // decoded messages of the six channels
  int64_t undecodable = 0;  // events on those channels that did not decode
  int64_t other = 0;        // events on other channels
  // Decoded states, setpoints, goals and trajectories whose joint values were left out because
  // they have another joint count than the config's chain: another robot's, or the wrong --config.
  int64_t other_joint_count = 0;
  uint64_t earliest_event_unix_us = 0;
};

// A converted LCM log: the new WPILOG (its extra header names the source and the Unix time of the
// earliest event) and what went into it.
struct Conversion {
  Writer writer;
  ConvertStats stats;
};

// Reads the LCM log at `lcm_path`: kCannotOpen when it cannot be opened, kNoMessages when it holds
// no message of the channels.
Result<Conversion, WpilogStatus> convertLcmLog(const std::string& lcm_path, const config::ChannelNames& channels,
                                               const MechanismGeometry& geometry);

}  // namespace cyber::wpilog

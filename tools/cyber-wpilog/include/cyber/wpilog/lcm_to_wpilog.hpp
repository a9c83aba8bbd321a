#pragma once
// An lcm-logger log of a cyber-planner session as WPILOG entries under /CyberPlanner/ (the names
// and units are listed in docs/operations.md, "AdvantageScope"). Timestamps are the logger's
// receive times in µs from the log's earliest event (not its first: lcm-logger's file order is not
// quite time order); trajectory samples are placed on that clock through the offset between the
// message's receive time and its utime.

#include <array>
#include <cstdint>
#include <string>

#include "cyber/config/daemon_settings.hpp"
#include "cyber/planner.hpp"
#include "cyber/result.hpp"
#include "cyber/wpilog/wpilog_status.hpp"
#include "cyber/wpilog/wpilog_writer.hpp"

namespace cyber::wpilog {

// What the mechanism views need of the robot: the rail and the arm's reach.
// What the logged mechanism drawings need of the robot: its chain and how far each link's
// outline reaches along its own x axis.
struct MechanismGeometry {
  planner::JointChain chain;
  std::array<double, planner::kJointCount> link_length_m{};
};
MechanismGeometry mechanismGeometry(const planner::RobotModel& robot);

struct ConvertStats {
  int64_t events = 0;       // events in the LCM log
  int64_t converted = 0;    // decoded messages of the six channels
  int64_t undecodable = 0;  // events on those channels that did not decode
  int64_t other = 0;        // events on other channels
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

#pragma once
// Command line of cyber-goal: send one goal to cyber-plannerd and wait for its final status.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "cyber/cli/argument_status.hpp"
#include "cyber/config/daemon_settings.hpp"
#include "cyber/config/load_config.hpp"

namespace cyber::tools {

struct GoalArguments {
  std::array<double, 2> position{0.0, 0.0};  // joint 0, joint 1 (config order), m or rad
  std::string pose_name;                     // --to NAME: a pose of --config's, for the held pieces
  std::string config_path;                   // empty: none; needed only to look up pose_name
  std::vector<std::string> pieces;           // held pieces by the config's names
  std::string scene;
  double scene_offset_m = 0.0;
  std::int64_t request_id = -1;                  // -1: derive one from the clock
  std::string lcm_url = config::kDefaultLcmUrl;  // the daemon's default (docs/lcm.md)
  double timeout_s = 10.0;
  bool wait_for_daemon = true;
  bool help = false;
};

// NaN and infinite targets and offsets, unknown, repeated or too many piece names are accepted on
// purpose: cyber-goal reads a config only to look up a pose name, and the daemon's answer is the
// one to see. A pose name without --config is a bad command line.
Result<GoalArguments, cli::ArgumentStatus> parseGoalArguments(const std::vector<std::string>& args);

// The target to send: --to's numbers, or its pose name looked up in `config` for the held pieces
// (which must then be the config's: the name is one of their set's poses).
Result<std::array<double, 2>, cli::ArgumentStatus> goalPosition(const GoalArguments& args,
                                                                const config::Config& config);

std::string goalUsage();

// Exit codes.
inline constexpr int kExitDone = 0;
inline constexpr int kExitLcm = 1;
inline constexpr int kExitUsage = cli::kExitBadUsage;
inline constexpr int kExitRejected = 3;
inline constexpr int kExitFailed = 4;
inline constexpr int kExitCancelled = 5;
inline constexpr int kExitTimeout = 6;

}  // namespace cyber::tools

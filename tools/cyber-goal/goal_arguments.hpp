#pragma once
// Command line of cyber-goal: send one goal to cyber-plannerd and wait for its final status.

#include <cstdint>
#include <string>
#include <vector>

#include "cyber/cli/argument_status.hpp"
#include "cyber/config/daemon_settings.hpp"
#include "cyber/config/load_config.hpp"

namespace cyber::tools {

struct GoalArguments {
  std::vector<double> position;     // one per joint (config order), m or rad; empty for a name
  std::string pose_name;            // --to NAME: sent for the daemon to resolve for the held pieces
  std::string config_path;          // empty: none; only to check pose_name before sending it
  std::vector<std::string> pieces;  // held pieces by the config's names
  std::string scene;
  double scene_offset_m = 0.0;
  std::int64_t request_id = -1;                  // -1: derive one from the clock
  std::string lcm_url = config::kDefaultLcmUrl;  // the daemon's default (docs/lcm.md)
  double timeout_s = 10.0;
  bool wait_for_daemon = true;
  bool help = false;
};

// NaN and infinite targets and offsets, any count of values, unknown, repeated or too many piece
// names and unknown pose names are accepted on purpose: the daemon judges a goal with its own
// configuration, and its answer is the one to see.
Result<GoalArguments, cli::ArgumentStatus> parseGoalArguments(const std::vector<std::string>& args);

// The target as `config` sees it: --to's numbers, or its pose name looked up for the held pieces
// (which must then be the config's: the name is one of their set's poses). cyber-goal sends the
// name itself, so that the daemon resolves it with its configuration; this only catches a typo
// before sending.
Result<std::vector<double>, cli::ArgumentStatus> goalPosition(const GoalArguments& args, const config::Config& config);

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

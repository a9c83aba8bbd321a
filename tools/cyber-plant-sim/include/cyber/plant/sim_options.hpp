#pragma once
// The command line of cyber-plant-sim (docs/testing.md, "Plant simulator").

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cyber/cli/argument_status.hpp"
#include "cyber/planner.hpp"
#include "cyber/plant/fault_schedule.hpp"
#include "cyber/plant/plant_simulation.hpp"

namespace cyber::plant {

struct SimOptions {
  std::optional<std::string> config_path;    // --config; the embedded reference robot otherwise
  std::optional<std::string> can_interface;  // --can; the config's [daemon] can_interface otherwise
  std::optional<std::string> lcm_url;        // --lcm-url; the config's [daemon] lcm_url otherwise
  // --initial Q0[,Q1[,Q2]], one per joint (checked against the config); default: the config's
  // first named pose, else the middle of every range.
  std::optional<planner::JointVector> initial_q;
  std::vector<std::string> pieces;          // --pieces NAME[,NAME...]: game pieces held (ARM_STATE, the plant's mass)
  double state_rate_hz = 100.0;             // --state-rate HZ
  bool heartbeat = true;                    // --no-heartbeat turns it off from the start
  std::vector<FaultEvent> faults;           // --fault KIND@WHEN, repeatable
  std::optional<std::string> log_path;      // --log FILE: CSV of the simulated state
  std::optional<std::string> control_path;  // --control FIFO: fault kinds, one per line, applied at once
  double duration_s = 0.0;                  // --duration S; 0 runs until SIGINT/SIGTERM
  double setpoint_timeout_s = 0.1;          // --setpoint-timeout S
  // --bandwidth RADPS: the closed-loop bandwidth the controllers' gains are derived for.
  double controller_bandwidth_radps = kDefaultControllerBandwidth_radps;
  // --joint0-gains, --joint1-gains, --joint2-gains KP,KD (only for joints the config has).
  std::array<std::optional<PdGains>, kMaxJoints> joint_gains;
  int realtime_priority = 0;  // --realtime PRIO: SCHED_FIFO 1..99 (0: normal scheduling)
};

struct SimArguments {
  bool help = false;  // --help: print usage and exit 0
  SimOptions options;
};

Result<SimArguments, cli::ArgumentStatus> parseSimArguments(const std::vector<std::string>& args);

std::string_view simUsage();

}  // namespace cyber::plant

#pragma once
// The command line of cyber-plant-sim (docs/testing.md, "Plant simulator").

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cyber/cli/parsed.hpp"
#include "cyber/planner/types.hpp"
#include "cyber/plant/fault_schedule.hpp"
#include "cyber/plant/plant_simulation.hpp"

namespace cyber::plant {

struct SimOptions {
  std::optional<std::string> config_path;    // --config; the embedded reference robot otherwise
  std::optional<std::string> can_interface;  // --can; the config's [daemon] can_interface otherwise
  std::optional<std::string> lcm_url;        // --lcm-url; the config's [daemon] lcm_url otherwise
  planner::JointVector initial_q = planner::JointVector(0.20, 1.57);  // --initial T,THETA (STOW)
  std::vector<std::string> pieces;                 // --pieces NAME[,NAME...]: game pieces reported as held in ARM_STATE
  double state_rate_hz = 100.0;                    // --state-rate HZ
  bool heartbeat = true;                           // --no-heartbeat turns it off from the start
  std::vector<FaultEvent> faults;                  // --fault KIND@WHEN, repeatable
  std::optional<std::string> log_path;             // --log FILE: CSV of the simulated state
  std::optional<std::string> control_path;         // --control FIFO: fault kinds, one per line, applied at once
  double duration_s = 0.0;                         // --duration S; 0 runs until SIGINT/SIGTERM
  double setpoint_timeout_s = 0.1;                 // --setpoint-timeout S
  PdGains elevator_gains = kDefaultElevatorGains;  // --elevator-gains KP,KD
  PdGains arm_gains = kDefaultArmGains;            // --arm-gains KP,KD
  int realtime_priority = 0;                       // --realtime PRIO: SCHED_FIFO 1..99 (0: normal scheduling)
};

struct SimArguments {
  bool help = false;  // --help: print usage and exit 0
  SimOptions options;
};

cli::Parsed<SimArguments> parseSimArguments(const std::vector<std::string>& args);

std::string_view simUsage();

}  // namespace cyber::plant

#pragma once
// The --control FIFO of cyber-plant-sim: a test writes commands, one per line, and the simulator
// carries each out at once:
//   KIND            inject fault KIND (`echo disable > FIFO`)
//   KIND if-moving  only if a setpoint with a non-zero velocity arrived in the last 20 ms
//                   (so a test hits a motion, not a daemon that just stopped on its own)
//   probe           log whether the setpoints are moving in that sense
// This splits the byte stream into commands.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cyber/plant/fault_schedule.hpp"

namespace cyber::plant {

struct ControlCommand {
  std::optional<FaultKind> kind;  // the fault to inject; empty for probe or a bad line
  bool if_moving = false;         // KIND if-moving
  bool probe = false;             // probe
  std::string line;               // as received, trimmed; a bad line has neither kind nor probe
};

// One line's command (no newline).
ControlCommand parseControlLine(std::string_view line);

class ControlLines {
 public:
  // Appends bytes; returns the commands of the lines they completed. Empty lines are skipped,
  // surrounding white space is ignored, and a line longer than kMaxLine is cut there.
  std::vector<ControlCommand> feed(std::string_view bytes);

  static constexpr std::size_t kMaxLine = 256;

 private:
  std::string partial_;
};

}  // namespace cyber::plant

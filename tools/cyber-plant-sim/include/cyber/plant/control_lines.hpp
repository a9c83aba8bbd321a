#pragma once
// The --control FIFO of cyber-plant-sim: a test writes fault kinds, one per line (`echo disable >
// FIFO`), and the simulator applies each at once. This splits the byte stream into commands.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cyber/plant/fault_schedule.hpp"

namespace cyber::plant {

struct ControlCommand {
  std::optional<FaultKind> kind;  // empty: the line named no fault kind
  std::string line;               // as received, without the newline
};

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

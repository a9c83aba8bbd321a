#include "cyber/plant/control_lines.hpp"

namespace cyber::plant {

namespace {

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

}  // namespace

std::vector<ControlCommand> ControlLines::feed(std::string_view bytes) {
  std::vector<ControlCommand> commands;
  for (char c : bytes) {
    if (c != '\n') {
      if (partial_.size() < kMaxLine) partial_ += c;
      continue;
    }
    const std::string_view line = trim(partial_);
    if (!line.empty()) commands.push_back(ControlCommand{parseFaultKind(line), std::string(line)});
    partial_.clear();
  }
  return commands;
}

}  // namespace cyber::plant

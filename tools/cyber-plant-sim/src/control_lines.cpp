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

ControlCommand parseControlLine(std::string_view text) {
  const std::string_view line = trim(text);
  ControlCommand command;
  command.line = std::string(line);
  if (line == "probe") {
    command.probe = true;
    return command;
  }
  constexpr std::string_view kIfMoving = " if-moving";
  std::string_view name = line;
  if (name.ends_with(kIfMoving)) {
    name = trim(name.substr(0, name.size() - kIfMoving.size()));
    command.if_moving = true;
  }
  command.kind = parseFaultKind(name);
  if (!command.kind) command.if_moving = false;
  return command;
}

std::vector<ControlCommand> ControlLines::feed(std::string_view bytes) {
  std::vector<ControlCommand> commands;
  for (char c : bytes) {
    if (c != '\n') {
      if (partial_.size() < kMaxLine) partial_ += c;
      continue;
    }
    if (!trim(partial_).empty()) commands.push_back(parseControlLine(partial_));
    partial_.clear();
  }
  return commands;
}

}  // namespace cyber::plant

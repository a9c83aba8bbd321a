#include "cyber/plant/fault_schedule.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "cyber/cli/number_text.hpp"

namespace cyber::plant {

namespace {

constexpr std::array<std::pair<FaultKind, std::string_view>, 8> kNames{{
    {FaultKind::kHeartbeatStop, "heartbeat-stop"},
    {FaultKind::kHeartbeatResume, "heartbeat-resume"},
    {FaultKind::kHeartbeatDisabled, "heartbeat-disabled"},
    {FaultKind::kHeartbeatEnabled, "heartbeat-enabled"},
    {FaultKind::kBroadcastDisable, "disable"},
    {FaultKind::kSilent, "silent"},
    {FaultKind::kStateResume, "state-resume"},
    {FaultKind::kExit, "exit"},
}};

constexpr std::string_view kMotionPrefix = "motion";
constexpr int kMaxMotionIndex = 999;

}  // namespace

std::string_view toString(FaultKind kind) {
  for (const auto& [k, name] : kNames) {
    if (k == kind) return name;
  }
  return "unknown";
}

std::optional<FaultKind> parseFaultKind(std::string_view name) {
  for (const auto& [kind, text] : kNames) {
    if (text == name) return kind;
  }
  return std::nullopt;
}

FaultParse parseFault(std::string_view text) {
  const auto at = text.find('@');
  if (at == std::string_view::npos) {
    return {std::nullopt, "fault '" + std::string(text) + "' is not KIND@SECONDS"};
  }
  const auto kind = parseFaultKind(text.substr(0, at));
  if (!kind) {
    std::string known;
    for (const auto& [k, name] : kNames) known += (known.empty() ? "" : ", ") + std::string(name);
    return {std::nullopt, "unknown fault '" + std::string(text.substr(0, at)) + "' (known: " + known + ")"};
  }
  const std::string bad_time =
      "fault time in '" + std::string(text) + "' must be SECONDS, motion+SECONDS or motionN+SECONDS with SECONDS >= 0";
  std::string_view when = text.substr(at + 1);
  int motion = 0;
  if (when.starts_with(kMotionPrefix)) {
    when.remove_prefix(kMotionPrefix.size());
    const auto plus = when.find('+');
    if (plus == std::string_view::npos) return {std::nullopt, bad_time};
    const std::string_view index = when.substr(0, plus);
    if (index.empty()) {
      motion = 1;
    } else {
      for (char c : index) {
        if (c < '0' || c > '9' || motion > kMaxMotionIndex) return {std::nullopt, bad_time};
        motion = motion * 10 + (c - '0');
      }
      if (motion < 1 || motion > kMaxMotionIndex) return {std::nullopt, bad_time};
    }
    when.remove_prefix(plus + 1);
  }
  const auto seconds = cli::parseNumber(when);
  if (!seconds || *seconds < 0.0) return {std::nullopt, bad_time};
  return {FaultEvent{*kind, motion, *seconds}, {}};
}

OutputSwitches applyFault(OutputSwitches switches, FaultKind kind) {
  switch (kind) {
    case FaultKind::kHeartbeatStop: switches.heartbeat = false; break;
    case FaultKind::kHeartbeatResume: switches.heartbeat = true; break;
    case FaultKind::kHeartbeatDisabled: switches.heartbeat_enabled = false; break;
    case FaultKind::kHeartbeatEnabled: switches.heartbeat_enabled = true; break;
    case FaultKind::kBroadcastDisable: break;
    case FaultKind::kSilent: switches.publish_state = false; break;
    case FaultKind::kStateResume: switches.publish_state = true; break;
    case FaultKind::kExit: switches.exit = true; break;
  }
  return switches;
}

FaultSchedule::FaultSchedule(std::vector<FaultEvent> events) : pending_(std::move(events)) {}

void FaultSchedule::motionStarted(int index, double t_s) {
  if (index < 1) return;
  if (motion_starts_s_.size() < static_cast<std::size_t>(index))
    motion_starts_s_.resize(static_cast<std::size_t>(index));
  auto& start = motion_starts_s_[static_cast<std::size_t>(index - 1)];
  if (!start) start = t_s;
}

std::optional<double> FaultSchedule::dueTime(const FaultEvent& event) const {
  if (event.motion == 0) return event.offset_s;
  const auto index = static_cast<std::size_t>(event.motion - 1);
  if (index >= motion_starts_s_.size() || !motion_starts_s_[index]) return std::nullopt;
  return *motion_starts_s_[index] + event.offset_s;
}

std::optional<double> FaultSchedule::nextDue_s() const {
  std::optional<double> earliest;
  for (const auto& event : pending_) {
    const auto due = dueTime(event);
    if (due && (!earliest || *due < *earliest)) earliest = due;
  }
  return earliest;
}

std::vector<FaultKind> FaultSchedule::takeDue(double now_s) {
  std::vector<std::pair<double, std::size_t>> due;  // (time, command-line index)
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    const auto t = dueTime(pending_[i]);
    if (t && *t <= now_s) due.emplace_back(*t, i);
  }
  std::sort(due.begin(), due.end());
  std::vector<FaultKind> kinds;
  kinds.reserve(due.size());
  for (const auto& [t, i] : due) kinds.push_back(pending_[i].kind);
  // Erase from the back so the indices stay valid.
  std::vector<std::size_t> indices;
  for (const auto& [t, i] : due) indices.push_back(i);
  std::sort(indices.rbegin(), indices.rend());
  for (std::size_t i : indices) pending_.erase(pending_.begin() + static_cast<std::ptrdiff_t>(i));
  return kinds;
}

}  // namespace cyber::plant

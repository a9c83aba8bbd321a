#pragma once
// Faults the simulator injects on a schedule given on its command line, so a test can drive them
// deterministically: `--fault KIND@SECONDS` (seconds after start-up) or `--fault
// KIND@motionN+SECONDS` (seconds after the N-th motion started; `motion+` is `motion1+`). A motion
// starts with a setpoint frame carrying a non-zero velocity while the stream was at rest (no
// setpoint yet, or the latest frames of every joint had zero velocity).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cyber::plant {

enum class FaultKind {
  kHeartbeatStop,      // heartbeat-stop: send no roboRIO heartbeat
  kHeartbeatResume,    // heartbeat-resume: send it again
  kHeartbeatDisabled,  // heartbeat-disabled: keep sending it, without the enabled/watchdog bits
  kHeartbeatEnabled,   // heartbeat-enabled: with the bits again
  kBroadcastDisable,   // disable: one broadcast disable frame (extended id 0, no data)
  kSilent,             // silent: publish no ARM_STATE (the simulation keeps running)
  kStateResume,        // state-resume: publish ARM_STATE again
  kExit,               // exit: end the simulation (as SIGTERM does)
};

struct FaultEvent {
  FaultKind kind = FaultKind::kExit;
  int motion = 0;         // 0: after start-up; N >= 1: after the N-th motion started
  double offset_s = 0.0;  // >= 0

  bool operator==(const FaultEvent&) const = default;
};

std::string_view toString(FaultKind kind);
std::optional<FaultKind> parseFaultKind(std::string_view name);

struct FaultParse {
  std::optional<FaultEvent> event;
  std::string error;  // set when event is empty
};
// Parses "KIND@SECONDS", "KIND@motion+SECONDS" or "KIND@motionN+SECONDS" (N = 1..999).
FaultParse parseFault(std::string_view text);

// What the simulator sends and publishes; faults switch these.
struct OutputSwitches {
  bool heartbeat = true;          // send the heartbeat at all
  bool heartbeat_enabled = true;  // with the enabled and system-watchdog bits
  bool publish_state = true;      // publish ARM_STATE
  bool exit = false;              // end the run

  bool operator==(const OutputSwitches&) const = default;
};

// The switches after a fault; kBroadcastDisable changes none (it is a one-shot frame).
OutputSwitches applyFault(OutputSwitches switches, FaultKind kind);

// Pending faults. Events due at the same time fire in command-line order.
class FaultSchedule {
 public:
  explicit FaultSchedule(std::vector<FaultEvent> events);

  // Motion number `index` (1, 2, ...) started at t_s: anchors the events relative to it. A number
  // seen before keeps its first time.
  void motionStarted(int index, double t_s);
  // Due time of the earliest pending event whose anchor is known.
  [[nodiscard]] std::optional<double> nextDue_s() const;
  // Removes and returns the events due at or before now_s, earliest first.
  std::vector<FaultKind> takeDue(double now_s);
  [[nodiscard]] std::size_t pending() const { return pending_.size(); }

 private:
  [[nodiscard]] std::optional<double> dueTime(const FaultEvent& event) const;

  std::vector<FaultEvent> pending_;                     // command-line order
  std::vector<std::optional<double>> motion_starts_s_;  // [N - 1]: start of motion N
};

}  // namespace cyber::plant

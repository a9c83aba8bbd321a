#pragma once
// The setpoint streamer's logic, one call per timer period. Single-threaded and allocation-free:
// programs arrive as pointers the caller owns the memory of, and leave through `retired` for the
// caller to free elsewhere. The gate is evaluated on every tick, so a stale heartbeat stops motion
// within one period even when the event loop is busy.

#include <array>
#include <cstdint>

#include "cyber/can/setpoint_codec.hpp"
#include "cyber/can/status_codec.hpp"
#include "cyber/daemon/hold_model.hpp"
#include "cyber/daemon/mono_time.hpp"
#include "cyber/daemon/motion_gate.hpp"
#include "cyber/daemon/program.hpp"
#include "cyber/daemon/stream_event.hpp"

namespace cyber::daemon {

// The status frame's modes (docs/can-protocol.md): the codec's own enum (and can::toString).
using StreamMode = can::Mode;

// What one setpoint frame can carry (the codec's ranges); anything else is a fault.
struct SetpointLimits {
  double position = can::kMaxPositionMagnitude;
  double velocity = can::kMaxVelocityMagnitude;
  double volts = can::kMaxVoltageMagnitude;
};

struct StreamerSettings {
  GateSettings gate;
  SetpointLimits limits;
  double fault_stop_s = 1.0;  // after a fault nothing is streamed this long, then the measured position is held
};

struct TickOutput {
  static constexpr int kMaxEvents = 8;
  static constexpr int kMaxRetired = 3;

  bool send_setpoints = false;
  JointSetpoints setpoints;
  StreamMode mode = StreamMode::kNoState;
  GateReason gate_reason = GateReason::kNoState;
  std::int64_t request_id = -1;  // segment streamed, or the last one (held target); -1 none
  double segment_time_s = 0.0;
  double remaining_s = 0.0;  // until the program comes to rest

  std::array<StreamEvent, kMaxEvents> events{};
  int event_count = 0;
  std::array<Program*, kMaxRetired> retired{};
  int retired_count = 0;

  void reset();
  // Both abort past their capacity (a defect of the streamer: see streamer.cpp).
  void push(const StreamEvent& event);
  void retire(Program* program);
};

class Streamer {
 public:
  Streamer(const HoldModel& hold, const StreamerSettings& settings);
  ~Streamer();
  Streamer(const Streamer&) = delete;
  Streamer& operator=(const Streamer&) = delete;

  // One period at `now`. `offered` (may be null) is the newest program handed over since the last
  // tick; the streamer either adopts it or returns it in out.retired. `stop_requested` holds the
  // commanded position (shutdown). Never allocates.
  void tick(MonoNs now, const RobotInputs& inputs, Program* offered, bool stop_requested, TickOutput& out);

  // Gives back the program it still owns (on shutdown), or null.
  Program* releaseProgram();

  [[nodiscard]] std::uint64_t epoch() const { return epoch_; }

 private:
  void stop(MonoNs now, GateReason reason, TickOutput& out);
  void holdOwn(MonoNs now, const JointVector& q, HoldCause cause, TickOutput& out);
  // The streamer's own hold at q on a new epoch, reporting `event` (kind and cause set by the caller).
  void restartOwnHold(MonoNs now, const JointVector& q, StreamEvent event, TickOutput& out);
  void consider(MonoNs now, Program* offered, TickOutput& out);
  void reject(MonoNs now, Program* offered, RejectReason reason, TickOutput& out);
  [[nodiscard]] bool withinLimits(const JointSetpoints& setpoints) const;
  void dropOwned(TickOutput& out);
  // The tick's parts, in order: the gate (counting each disable and release once), the answer
  // while it is closed, the stop on a sample outside the limits, the executing and done events, and
  // the setpoints sent.
  GateVerdict gate(MonoNs now, const RobotInputs& inputs);
  void closedGate(MonoNs now, const GateVerdict& verdict, Program* offered, TickOutput& out);
  void sampleFault(MonoNs now, const ProgramSample& sample, TickOutput& out);
  void reportProgress(MonoNs now, const ProgramSample& sample, TickOutput& out);
  void send(MonoNs now, const ProgramSample& sample, TickOutput& out);

  HoldModel hold_;
  StreamerSettings settings_;
  Program own_;               // the streamer's own hold program, reused
  Program* program_ = &own_;  // own_ or an adopted one (owned until retired)
  bool running_ = false;      // streaming (holding or moving); false while the gate is closed
  bool shutdown_hold_ = false;
  std::uint64_t epoch_ = 0;
  MonoNs last_sample_ns_ = kNever;
  JointVector last_position_;
  std::int64_t executing_request_ = -1;
  MonoNs executing_end_ns_ = kNever;
  std::int64_t last_request_ = -1;
  bool done_reported_ = true;
  MonoNs fault_until_ns_ = kNever;
  std::uint32_t disables_seen_ = 0;  // RobotInputs::broadcast_disable_count at the last tick
  std::uint32_t releases_seen_ = 0;  // RobotInputs::release_generation at the last tick
};

}  // namespace cyber::daemon

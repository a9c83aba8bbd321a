#pragma once
// What the streamer tells the event loop. Fixed-size values: they travel through a lock-free queue.

#include <cstdint>
#include <string_view>

#include "cyber/daemon/mono_time.hpp"
#include "cyber/daemon/motion_gate.hpp"
#include "cyber/daemon/setpoint_source.hpp"

namespace cyber::daemon {

enum class StreamEventKind {
  kAdopted,    // program_id is running now; start_ns = start of its last segment
  kRejected,   // program_id was not taken (reject_reason); it never ran
  kExecuting,  // request_id's segment is being streamed
  kDone,       // request_id's segment finished; holding its end position
  kStopped,    // motion stopped (gate closed, reason): nothing is streamed; new epoch
  kHolding,    // the streamer holds `position` on its own (enabled again, shutdown); new epoch
  kFault,      // a setpoint could not be streamed (non-finite or out of the frame's range)
};

enum class RejectReason {
  kLate,       // the splice time had already been streamed from the old program
  kStaleBase,  // the program was built on a program or epoch that is no longer running
};

enum class HoldCause { kEnabled, kShutdown };

struct StreamEvent {
  StreamEventKind kind = StreamEventKind::kAdopted;
  MonoNs time_ns = 0;
  std::uint64_t program_id = 0;
  std::int64_t request_id = -1;
  std::uint64_t epoch = 0;
  MonoNs start_ns = 0;
  JointVector position;
  GateReason gate_reason = GateReason::kOpen;
  RejectReason reject_reason = RejectReason::kLate;
  HoldCause hold_cause = HoldCause::kEnabled;
  // kStopped, kHolding: the RobotInputs::release_generation the streamer had seen, so the
  // coordinator can tell a hold taken before a release (or its end) from the one after.
  std::uint32_t release_generation = 0;
};

std::string_view toString(StreamEventKind kind);
std::string_view toString(RejectReason reason);

}  // namespace cyber::daemon
